#!/usr/bin/env python3
"""Input files that change between a stop and a resume (doc/user_guide.md
§6, doc/decisions.md D161): the checkpoint records a digest of every file
the model reads besides the prm (here the STEP tools of
prm/square_cup_step.prm and a polygon outline file); a resume after one of
them changed is refused like a changed parameter, with exit code 2 naming
the file and its parameter, and the output directory left byte for byte as
it was; with the files back as they were, the resume runs.
"""
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402

CASE = """include prm/square_cup_step.prm
subsection Geometry
  set Blank outline         = polygon
  set Outline file          = outline.txt
  set Elements along radius = 6
end
subsection Process
  set Final load = %g
end
subsection Load stepping
  set Initial increment = 0.1
  set Maximum increment = 0.1
end
subsection Checkpoint
  set Interval = 1
end
"""
OUTLINE = "-75 -75\n75 -75\n75 75\n-75 75\n"


def deepdraw(args, work, prm, *extra):
    result = subprocess.run([args.deepdraw, str(prm), "--output-directory",
                             "out", *extra], cwd=work, capture_output=True,
                            text=True)
    print("  exit %d: %s" % (result.returncode, result.stderr.strip()[:400]))
    return result


def main():
    args, source, work = script_test.start(__doc__)
    case = work / "case"
    shutil.copytree(source / "prm" / "tools" / "square_cup",
                    case / "tools" / "square_cup")
    outline = case / "outline.txt"
    outline.write_text(OUTLINE)
    first, longer = case / "first.prm", case / "longer.prm"
    first.write_text(CASE % 0.2)
    longer.write_text(CASE % 0.4)
    result = deepdraw(args, work, first)
    if result.returncode != 0:
        sys.exit("FAILED: the first run: " + result.stdout[-2000:])
    checkpoint = str(pathlib.Path("out") / "checkpoint.bin")
    failures = []
    die = case / "tools" / "square_cup" / "die.step"
    die_text = die.read_bytes()
    changes = [
        (die, die_text + b"\n", "Contact/Tool 2/File"),
        (outline, OUTLINE.replace("75", "76").encode(),
         "Geometry/Outline file"),
    ]
    for path, changed, parameter in changes:
        original = path.read_bytes()
        path.write_bytes(changed)
        before = script_test.snapshot(work / "out")
        for extra in (("--check", "--resume"), ("--resume",)):
            result = deepdraw(args, work, longer, *extra)
            line = result.stderr.strip()
            if result.returncode != 2 or str(path) not in line \
                    or parameter not in line or checkpoint not in line \
                    or "\n" in line:
                failures.append("%s changed, %s: exit %d: %s"
                                % (path.name, extra[0], result.returncode,
                                   line))
        if script_test.snapshot(work / "out") != before:
            failures.append("%s changed: the output directory changed"
                            % path.name)
        path.write_bytes(original)
    result = deepdraw(args, work, longer, "--resume")
    if result.returncode != 0 or "resumed at load 0.2" not in result.stdout:
        failures.append("the unchanged files: the resume failed")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
