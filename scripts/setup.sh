#!/usr/bin/env bash
# Installs what deepdraw needs on Debian 12 (only the missing packages), then
# configures it in Release in ./build and builds it. Idempotent, no prompts.
#
#   scripts/setup.sh            the program only (build/deepdraw)
#   scripts/setup.sh --tests    also what the tests need, and every target
set -euo pipefail
cd "$(dirname "$0")/.."

# libmumps-dev comes with deal.II's PETSc and Trilinos, but deepdraw links it
# itself (D96).
packages=(libdeal.ii-dev libmumps-dev libopenblas0-serial cmake g++ make ccache)
targets=(--target deepdraw)
if [ "${1:-}" = "--tests" ]; then
  # numdiff and python3 for the tests; gnuplot-nox for study.png; and
  # python3-paraview, python3-numpy, xvfb and xauth (which xvfb-run needs;
  # only recommended by xvfb) for the paraview test (tests/paraview/).
  packages+=(numdiff python3 gnuplot-nox python3-paraview python3-numpy xvfb
             xauth)
  targets=()
fi
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log.tmp 2>&1 || { cat build.log.tmp; rm -f build.log.tmp; exit 1; }
rm -f build.log.tmp
cmake --build build -j "$jobs" "${targets[@]}"
