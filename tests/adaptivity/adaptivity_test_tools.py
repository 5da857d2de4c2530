"""Shared by the script tests of tests/adaptivity: the command line of a
script test (--deepdraw, --source-dir, --work-dir; tests/CMakeLists.txt), a
fresh work directory with prm/ linked into it, one run of deepdraw on a
parameter text, and CSV tables as rows of dictionaries."""
import argparse
import csv
import pathlib
import shutil
import subprocess


def prepare():
    """Parses the arguments and makes an empty work directory (prm/ linked,
    so that `include prm/...` works there); returns (args, work)."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--deepdraw", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    args = parser.parse_args()
    work = pathlib.Path(args.work_dir)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    (work / "prm").symlink_to(pathlib.Path(args.source_dir).resolve() / "prm",
                              target_is_directory=True)
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
