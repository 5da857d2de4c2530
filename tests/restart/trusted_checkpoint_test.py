#!/usr/bin/env python3
"""A checkpoint is verified whole before a resume touches anything
(doc/user_guide.md §6, doc/decisions.md D160): each damaged checkpoint
below is refused with exit code 2 and one line naming the checkpoint and
the field, and the output directory is left byte for byte as it was.

The base: tests/restart/short_cup.prm to load 0.5 (a checkpoint after
every increment). Each case copies it, damages checkpoint.bin and resumes
to load 1. Apart from the flipped bit (the checksum's case), the damaged
image is sealed again with a CRC-32 computed by checkpoint_image.py, so
that what refuses it is the range check. The same image converted to
format 3 (no checksum, no digests) resumes, and is refused when damaged
the same way. --check --resume says a damaged checkpoint is not valid. A
checkpoint that cannot be renamed into place leaves no .tmp file.
"""
import pathlib
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import script_test  # noqa: E402
from checkpoint_image import CheckpointImage  # noqa: E402
from script_test import snapshot  # noqa: E402

PRM = pathlib.Path(__file__).with_name("short_cup.prm")


def deepdraw(args, work, prm, output, *extra):
    result = subprocess.run([args.deepdraw, str(prm), "--output-directory",
                             str(output), *extra], cwd=work,
                            capture_output=True, text=True)
    print("  exit %d: %s" % (result.returncode, result.stderr.strip()[:400]))
    return result


def refused(args, work, prm, base, name, damage, expected, extra_check=None):
    """Copies base to work/name, damages its checkpoint with damage(image
    bytes) -> bytes, resumes; returns the failures."""
    print("case", name)
    case = work / name
    shutil.copytree(base, case)
    checkpoint = case / "checkpoint.bin"
    checkpoint.write_bytes(damage(checkpoint.read_bytes()))
    before = snapshot(case)
    failures = []
    for extra in (("--check", "--resume"), ("--resume",)):
        result = deepdraw(args, work, prm, case, *extra)
        line = result.stderr.strip()
        if result.returncode != 2:
            failures.append("%s %s: exit code %d, not 2"
                            % (name, extra[0], result.returncode))
        if str(checkpoint) not in line or expected not in line \
                or "\n" in line:
            failures.append("%s %s: the message does not name the "
                            "checkpoint and '%s' in one line: %s"
                            % (name, extra[0], expected, line))
        if snapshot(case) != before:
            failures.append("%s %s: the output directory changed"
                            % (name, extra[0]))
    if extra_check:
        failures += extra_check()
    return failures


def sealed_with(field, value):
    def damage(data):
        image = CheckpointImage(data)
        image.replace(field, value)
        return image.sealed()
    return damage


def main():
    args, _, work = script_test.start(__doc__)
    short = work / "short.prm"
    short.write_text("include %s\nsubsection Process\n  set Final load = "
                     "0.5\nend\n" % PRM)
    longer = work / "longer.prm"
    longer.write_text("include %s\nsubsection Process\n  set Final load = "
                      "1\nend\n" % PRM)
    base = work / "base"
    if deepdraw(args, work, short, base).returncode != 0:
        sys.exit("FAILED: the base run")
    failures = []
    image = CheckpointImage((base / "checkpoint.bin").read_bytes())
    if not image.check_crc():
        failures.append("deepdraw's CRC-32 differs from checkpoint_image.py's")
    print("checkpoint: %d bytes, load %g, next increment %g, tables %s, "
          "input files %s" % (len(image.data), image.double("load"),
                              image.double("next_increment"),
                              image.tables, image.input_files))

    def flip_vertex_bit(data):
        image = CheckpointImage(data)
        start = image.fields["vertices"][0] + 8 * 7 + 2
        image.data[start] ^= 0x04  # a mantissa bit of a coordinate
        return image.unsealed()
    failures += refused(args, work, longer, base, "flipped_bit",
                        flip_vertex_bit, "checksum")

    victim = work / "victim.csv"
    victim.write_text("not deepdraw's\n")

    def victim_table(data):
        image = CheckpointImage(data)
        image.replace_string("table_%d.name" % image.table_index("draw_in.csv"),
                             "../victim.csv")
        return image.sealed()

    def victim_untouched():
        if victim.read_text() != "not deepdraw's\n":
            return ["the victim outside the output directory was changed"]
        return []
    failures += refused(args, work, longer, base, "table_outside",
                        victim_table, "table name '../victim.csv'",
                        victim_untouched)

    failures += refused(args, work, longer, base, "next_increment_0",
                        sealed_with("next_increment", struct.pack("<d", 0.)),
                        "next increment = 0")
    failures += refused(args, work, longer, base, "next_increment_negative",
                        sealed_with("next_increment",
                                    struct.pack("<d", -0.1)),
                        "next increment = -0.1 ")
    failures += refused(args, work, longer, base, "load_1e300",
                        sealed_with("load", struct.pack("<d", 1e300)),
                        "load = 1e+300 lies outside")
    failures += refused(args, work, longer, base, "history_count",
                        sealed_with("history.count",
                                    struct.pack("<Q", 1 << 58)),
                        "history: a count of %d" % (1 << 58))

    def bad_table_sizes(data):
        # draw_in.csv (first) cut within its header, statistics.csv (later)
        # longer than it is: refused before either is touched.
        image = CheckpointImage(data)
        image.replace("table_%d.bytes" % image.table_index("draw_in.csv"),
                      struct.pack("<Q", 10))
        stats = image.table_index("statistics.csv")
        image.replace("table_%d.bytes" % stats,
                      struct.pack("<Q", image.tables[stats][1] + 1000))
        return image.sealed()
    failures += refused(args, work, longer, base, "table_size",
                        bad_table_sizes, "statistics.csv is shorter than")

    # Format 3 (no checksum, no digests) still resumes, with the range
    # checks.
    print("case format_3")
    shutil.copytree(base, work / "format_3")
    (work / "format_3" / "checkpoint.bin").write_bytes(image.as_format_3())
    result = deepdraw(args, work, longer, work / "format_3", "--resume")
    if result.returncode != 0 or "resumed at load 0.5" not in result.stdout:
        failures.append("a format-3 checkpoint did not resume")

    def format_3_next_0(data):
        damaged = CheckpointImage(data)
        damaged.replace("next_increment", struct.pack("<d", 0.))
        return damaged.as_format_3()
    failures += refused(args, work, longer, base, "format_3_next_increment",
                        format_3_next_0, "next increment = 0")

    # --check --resume of a whole checkpoint.
    result = deepdraw(args, work, longer, base, "--check", "--resume")
    if result.returncode != 0 or "checkpoint are valid" not in result.stdout:
        failures.append("--check --resume of a whole checkpoint: exit %d"
                        % result.returncode)

    # A checkpoint that cannot be renamed into place (a directory is in
    # its way): the run stops, and no checkpoint.bin.tmp is left.
    print("case rename")
    blocked = work / "blocked"
    (blocked / "checkpoint.bin" / "in_the_way").mkdir(parents=True)
    result = deepdraw(args, work, short, blocked)
    if result.returncode != 3 or "cannot rename" not in result.stderr:
        failures.append("a checkpoint that cannot be renamed: exit %d"
                        % result.returncode)
    if (blocked / "checkpoint.bin.tmp").exists():
        failures.append("checkpoint.bin.tmp left behind")
    script_test.finish(failures)


if __name__ == "__main__":
    main()
