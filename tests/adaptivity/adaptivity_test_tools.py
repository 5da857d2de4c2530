"""Shared by the script tests of tests/adaptivity: the command line of a
script test (--deepdraw, --source-dir, --work-dir; tests/CMakeLists.txt), a
fresh work directory with prm/ linked into it, one run of deepdraw on a
parameter text, and CSV tables as rows of dictionaries."""
import csv
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402  (tests/script_test.py)


def prepare():
    """Parses the arguments and makes an empty work directory (prm/ linked,
    so that `include prm/...` works there; tests/script_test.py); returns
    (args, work)."""
    args, _, work = script_test.start(__doc__)
    return args, work


def run(args, work, name, text):
    """Runs deepdraw on `text` (written to work/name.prm) with the output in
    work/name; stops the test if the run fails. Returns the output path."""
    prm = work / (name + ".prm")
    prm.write_text(text)
    output = work / name
    result = subprocess.run([args.deepdraw, str(prm), "--output-directory",
                             str(output), "--quiet"], cwd=work,
                            capture_output=True, text=True)
    print(result.stdout, result.stderr)
    if result.returncode != 0:
        raise SystemExit(f"FAILED: {name} exited with {result.returncode}")
    return output


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))
