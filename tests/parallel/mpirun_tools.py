"""Running deepdraw under mpirun for the tests of label parallel (D199):
oversubscribed (this machine has 2 cores and the tests run 3 ranks) and
allowed as root, as CI runs."""
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402,F401  (tests/script_test.py)

SHORT_CUP = (pathlib.Path(__file__).resolve().parent.parent / "restart"
             / "short_cup.prm")


def environment():
    env = dict(os.environ)
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    return env


def command(ranks, deepdraw, *arguments):
    """deepdraw's command line, under mpirun for ranks > 0 (0: without
    mpirun)."""
    launcher = ["mpirun", "--oversubscribe", "-np", str(ranks)] if ranks \
        else []
    return launcher + [str(deepdraw)] + [str(a) for a in arguments]


def run(ranks, deepdraw, work, *arguments, timeout=600):
    """Runs deepdraw with `ranks` ranks; returns (exit code, output)."""
    full = command(ranks, deepdraw, *arguments)
    print("running:", " ".join(full), flush=True)
    result = subprocess.run(full, cwd=work, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=timeout)
    print(result.stdout[-2000:], flush=True)
    return result.returncode, result.stdout


def start(ranks, deepdraw, work, *arguments):
    full = command(ranks, deepdraw, *arguments)
    print("starting:", " ".join(full), flush=True)
    return subprocess.Popen(full, cwd=work, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)


def newton_path(directory):
    """Per increment and iteration the columns that say which way Newton
    went: increment, load, iteration, contact changes."""
    rows = script_test.csv_rows(pathlib.Path(directory) / "newton.csv")
    return [(r["increment"], r["load"], r["iteration"], r["contact_changes"])
            for r in rows]
