#!/usr/bin/env python3
"""The dense kernels of OpenBLAS (D210). OpenBLAS reports the kernels it
loads with OPENBLAS_VERBOSE=2 ("Core: Haswell"); the CPU's instruction
sets are the kernel's flags in /proc/cpuinfo, an account independent of
both OpenBLAS and deepdraw.
- On a CPU with AVX2 and FMA the kernels deepdraw computes with are not
  OpenBLAS's generic "Prescott" (SSE3) ones; with AVX-512 F, BW, VL and DQ
  they are AVX-512 kernels. Debian 12's OpenBLAS falls back to Prescott on
  CPUs newer than it (Intel family 6 model 207 here), where the square
  cup's runs took 1.25 to 1.6 times as long.
- OPENBLAS_CORETYPE set by the user is kept: with Prescott the program
  loads Prescott once and is not started again.
- Either way the program does what it was asked (--help, exit 0).

    blas_kernels_test.py --deepdraw EXE --source-dir REPO --work-dir DIR
"""
import os
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402

AVX512_KERNELS = {"SkylakeX", "Cooperlake", "SapphireRapids"}


def cpu_flags():
    for line in open("/proc/cpuinfo"):
        if line.startswith("flags"):
            return set(line.split(":", 1)[1].split())
    return set()


def loaded_kernels(deepdraw, work, coretype):
    """The 'Core:' lines OpenBLAS printed while deepdraw --help ran, and
    its exit code."""
    env = dict(os.environ)
    env.pop("OPENBLAS_CORETYPE", None)
    env["OPENBLAS_VERBOSE"] = "2"
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    result = subprocess.run([deepdraw, "--help"], cwd=work, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=120)
    cores = re.findall(r"^Core: (\S+)", result.stdout, re.M)
    print(f"OPENBLAS_CORETYPE={coretype or '(unset)'}: exit code "
          f"{result.returncode}, Core lines {cores}")
    return cores, result.returncode


def main():
    args, _, work = script_test.start(__doc__)
    failures = []
    flags = cpu_flags()
    print("CPU flags:", " ".join(sorted(f for f in flags
                                         if f.startswith(("avx", "fma")))))
    cores, code = loaded_kernels(args.deepdraw, work, None)
    if code != 0:
        failures.append(f"--help: exit code {code}")
    if not cores:
        failures.append("OpenBLAS printed no 'Core:' line: is it the BLAS "
                        "(scripts/setup.sh installs libopenblas0-serial)?")
    elif {"avx512f", "avx512bw", "avx512vl", "avx512dq"} <= flags:
        if cores[-1] not in AVX512_KERNELS:
            failures.append(f"an AVX-512 CPU computes with {cores[-1]}")
    elif {"avx2", "fma"} <= flags and cores[-1] == "Prescott":
        failures.append("an AVX2 CPU computes with the generic Prescott "
                        "kernels")
    cores, code = loaded_kernels(args.deepdraw, work, "Prescott")
    if code != 0:
        failures.append(f"--help with OPENBLAS_CORETYPE=Prescott: exit code "
                        f"{code}")
    if not cores or set(cores) != {"Prescott"}:
        failures.append(f"the user's OPENBLAS_CORETYPE=Prescott gave {cores}")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
