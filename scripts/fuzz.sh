#!/usr/bin/env bash
# Bounded fuzzing of the tool-file reader, of the prm reading path and of
# the checkpoint reader (fuzz/*.cc, doc/decisions.md D54, D160): libFuzzer
# with the address and undefined-behaviour sanitizers, clang 14. Not part
# of ctest.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET ...]]   (default 120, all)
#
# TARGET: tool_file_fuzzer, prm_fuzzer, checkpoint_fuzzer (the last builds
# from the checkpoint reader's own sources only, in a minute).
# Installs clang-14 and libclang-rt-14-dev if missing (apt-get, as
# scripts/setup.sh does), configures and builds build-fuzz/
# (-DDEEPDRAW_FUZZ=ON), seeds each target's corpus with the repository's
# tool and prm files, runs each target for SECONDS, and prints per target
# the executions and the crashes (sanitizer reports, aborts, timeouts,
# out-of-memory). The corpora and any crash-*/timeout-*/oom-* inputs stay in
# build-fuzz/fuzz-work/<target>/ (replay: build-fuzz/fuzz/<target> FILE).
# Exit code 1 if any target crashed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds="${1:-120}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(tool_file_fuzzer prm_fuzzer checkpoint_fuzzer)
cd "$root"

packages=(clang-14 libclang-rt-14-dev cmake make)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "fuzz: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
      -DDEEPDRAW_FUZZ=ON > build-fuzz.log.tmp 2>&1 \
  || { cat build-fuzz.log.tmp; rm -f build-fuzz.log.tmp; exit 1; }
rm -f build-fuzz.log.tmp
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}"

# deal.II and muparser are not instrumented; their allocations at exit are
# not leaks of an input.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

status=0
for target in "${targets[@]}"; do
  work="build-fuzz/fuzz-work/$target"
  mkdir -p "$work/corpus"
  max_len=8192
  if [ "$target" = tool_file_fuzzer ]; then
    find tests -name '*.tool' -exec cp {} "$work/corpus/" \;
  elif [ "$target" = checkpoint_fuzzer ]; then
    # A checkpoint of each format: fuzz/seeds (format 4, a 2 x 1 x 1 bar)
    # and the format-1 one of tests/restart/data.
    cp fuzz/seeds/checkpoint_format_4.bin "$work/corpus/"
    cp tests/restart/data/checkpoint_format_1/output/checkpoint.bin \
       "$work/corpus/checkpoint_format_1.bin"
    max_len=$(( $(wc -c < fuzz/seeds/checkpoint_format_4.bin) * 2 ))
  else
    find prm tests -name '*.prm' -exec cp {} "$work/corpus/" \;
    # Seeds include prm/*.prm and name tool files in data/.
    ln -sfn "$root/prm" "$work/prm"
    ln -sfn "$root/tests/contact/data" "$work/data"
  fi
  echo "fuzz: $target for $seconds s ($(ls "$work/corpus" | wc -l) inputs in the corpus)"
  set +e
  (cd "$work" && "$root/build-fuzz/fuzz/$target" -max_total_time="$seconds" \
       -timeout=30 -rss_limit_mb=4096 -max_len="$max_len" -print_final_stats=1 \
       corpus > fuzz.log 2>&1)
  code=$?
  set -e
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/fuzz.log" \
               | grep -o '[0-9]*$' || echo 0)
  crashes=$(find "$work" -maxdepth 1 \( -name 'crash-*' -o -name 'timeout-*' \
                  -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)
  echo "fuzz: $target: ${executions:-0} executions, $crashes crash(es), libFuzzer exit code $code"
  if [ "$crashes" -gt 0 ] || [ "$code" -ne 0 ]; then
    status=1
    grep -E "ERROR|SUMMARY|fuzz:|runtime error" "$work/fuzz.log" | head -20 || true
  fi
done
exit $status
