"""Class "special_files" of the hostile-input suite (tests/input/
hostile_cases.py), issue 32 round two: paths that are not regular files
(named pipes as inputs and in place of outputs, devices), CAD files nested
too deep, a deleted working directory, outline and Gmsh files with limits,
scales and cells that cannot make an element, holder forces that do not
press, draw-in names that break CSV columns, --study on prm files a plain
run refuses, and --check on a locked output directory. Each case: exit code
2, one line naming the file or parameter, and an output directory that was
there before left byte for byte as it was.
"""
import fcntl
import math
import os

from hostile_prm import CUP, cup, sub

STUDY = ["--study", "Geometry/Layers through thickness = 1, 2"]
# A tool of TOOL_PRM's kind (hostile_cases.py): a flat die below the sheet.
TOOL_PRM = ("subsection Geometry\n  set Length = 2\n  set Width = 2\n"
            "  set Thickness = 0.5\n  set Elements along x = 2\n"
            "  set Elements along y = 2\n  set Layers through thickness = 1\n"
            "end\nsubsection Boundary conditions\n"
            "  set Prescribed displacements = zmax: uz = -0.01*t\nend\n"
            "subsection Contact\n  subsection Tool 1\n    set Name = die\n"
            "    set Geometry = %s\n    set File = %s\n"
            "    set Sheet surface = bottom\n  end\nend\n")
SQUARE = "-60 -60\n60 -60\n60 60\n-60 60\n"


def fifo(*paths):
    """setup: named pipes at paths (relative to the case directory)."""
    def make(context):
        for path in paths:
            full = context["directory"] / path
            full.parent.mkdir(parents=True, exist_ok=True)
            os.mkfifo(full)
    return make


def snapshot(directory):
    """{relative path: bytes, or the kind for what is not a file}."""
    result = {}
    for root, dirs, files in os.walk(directory):
        for name in dirs + files:
            path = os.path.join(root, name)
            key = os.path.relpath(path, directory)
            if os.path.isfile(path) and not os.path.islink(path):
                with open(path, "rb") as f:
                    result[key] = f.read()
            else:
                result[key] = "fifo" if not os.path.isdir(path) else "dir"
    return result


def existing_output(*fifos, files=None):
    """A case's output directory made before the run: regular files and
    named pipes; its check asserts that the run left it unchanged."""
    def setup(context):
        output = context["directory"] / "output"
        output.mkdir()
        for name, content in (files or {"statistics.csv": "t\n0\n"}).items():
            (output / name).write_text(content)
        for name in fifos:
            os.mkfifo(output / name)
        context["before"] = snapshot(output)

    def check(context):
        if snapshot(context["directory"] / "output") != context["before"]:
            return ["the output directory changed"]
        return []
    return dict(setup=setup, check=check, output="")


def holding_lock(case):
    """The runner's own process holds the lock of output/ while the case
    runs (a living run in that directory)."""
    def setup(context):
        output = context["directory"] / "output"
        output.mkdir()
        lock = open(output / ".deepdraw.lock", "w")
        fcntl.flock(lock, fcntl.LOCK_EX)
        context["lock"] = lock

    def cleanup(context):
        context["lock"].close()
    case.update(setup=setup, cleanup=cleanup, output="")
    return case


def blank(outline, entry, content, *messages, name, exit=2, args=None):
    path = "data/outline.txt" if outline == "polygon" else "data/blank.msh"
    case = dict(name=name, files={
        "case.prm": CUP + sub("Geometry", "Blank outline", outline)
        + sub("Geometry", entry, path), path: content}, exit=exit,
        messages=list(messages))
    if args:
        case["args"] = args
    return case


def msh(nodes, elements, header="2.2 0 8"):
    """A Gmsh 2.2 file of quadrangles (node numbers from 1)."""
    lines = ["$MeshFormat", header, "$EndMeshFormat", "$Nodes",
             str(len(nodes))]
    lines += ["%d %g %g 0" % (k + 1, x, y) for k, (x, y) in enumerate(nodes)]
    lines += ["$EndNodes", "$Elements", str(len(elements))]
    lines += ["%d 3 2 1 1 %s" % (k + 1, " ".join(map(str, n)))
              for k, n in enumerate(elements)]
    return "\n".join(lines + ["$EndElements"]) + "\n"


def leave_working_directory():
    """preexec: the child starts in a directory that is then removed."""
    os.mkdir("gone")
    os.chdir("gone")
    os.rmdir(os.path.abspath("."))


def pipe_cases():
    """Named pipes in place of input files: refused before one is opened
    (D164), naming the file and what it is."""
    pipe = "is a named pipe, not a regular file"
    return [
        dict(name="tool_file_fifo", setup=fifo("data/die.tool"),
             files={"case.prm": TOOL_PRM % ("file", "data/die.tool")},
             exit=2, messages=["die.tool: " + pipe + " (the tool file)"]),
        dict(name="step_file_fifo", setup=fifo("data/die.step"),
             files={"case.prm": TOOL_PRM % ("cad", "data/die.step")},
             exit=2, messages=["die.step: " + pipe + " (the CAD file)"]),
        dict(name="mesh_file_fifo", setup=fifo("data/blank.msh"),
             files={"case.prm": CUP + sub("Geometry", "Blank outline", "gmsh")
                    + sub("Geometry", "Mesh file", "data/blank.msh")},
             exit=2, messages=["blank.msh: " + pipe + " (the mesh file)"]),
        dict(name="outline_file_fifo", setup=fifo("data/outline.txt"),
             files={"case.prm": CUP + sub("Geometry", "Blank outline",
                                          "polygon")
                    + sub("Geometry", "Outline file", "data/outline.txt")},
             exit=2, messages=["outline.txt: " + pipe]),
        dict(name="included_prm_fifo", setup=fifo("more.prm"),
             files={"case.prm": CUP + "include more.prm\n"}, exit=2,
             messages=["more.prm: " + pipe, "included from case.prm"]),
        dict(name="mesh_file_dev_zero",
             files={"case.prm": CUP + sub("Geometry", "Blank outline", "gmsh")
                    + sub("Geometry", "Mesh file", "/dev/zero")}, exit=2,
             messages=["/dev/zero: is a character device, not a regular "
                       "file (the mesh file)"]),
        dict(name="checkpoint_fifo", files=cup(),
             args=["case.prm", "--output-directory", "output", "--resume"],
             exit=2, messages=["checkpoint.bin: " + pipe],
             **existing_output("checkpoint.bin")),
        dict(name="statistics_fifo", files=cup(), exit=2,
             messages=["output/statistics.csv: " + pipe
                       + "; deepdraw would write its results there"],
             **existing_output("statistics.csv", files={"x.txt": "x"})),
        dict(name="vtu_fifo", files=cup(), exit=2,
             messages=["solution-00000.vtu: " + pipe],
             **existing_output("solution-00000.vtu")),
        dict(name="temporary_fifo", files=cup(), exit=2,
             messages=["checkpoint.bin.tmp: " + pipe],
             **existing_output("checkpoint.bin.tmp")),
        dict(name="check_reports_output_fifo", files=cup(),
             args=["--check", "case.prm", "--output-directory", "output"],
             exit=2, messages=["statistics.csv: " + pipe],
             **existing_output("statistics.csv", files={"x.txt": "x"})),
        dict(name="study_csv_fifo", files=cup(),
             args=["case.prm", "--output-directory", "output"] + STUDY,
             exit=2, messages=["study.csv: " + pipe],
             **existing_output("study.csv", files={"x.txt": "x"})),
    ]


def crash_cases():
    """What took the process down (D165-D167): exit 2 and one line."""
    deep = ("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=A(" + "(" * 100000
            + ")" * 100000 + ");\nENDSEC;\nEND-ISO-10303-21;\n")
    return [
        dict(name="step_nested_100000_deep",
             files={"case.prm": TOOL_PRM % ("cad", "data/die.step"),
                    "data/die.step": deep}, exit=2,
             messages=["die.step:5: parentheses nested more than 100 deep"]),
        dict(name="study_prm_includes_itself",
             files={"case.prm": "include case.prm\n"},
             args=["case.prm", "--output-directory", "output"] + STUDY,
             exit=2, messages=["case.prm:1", "include cycle"]),
        dict(name="study_binary_prm",
             files={"case.prm": b"\x7fELF\x02\x01\x01\x00" + bytes(range(256))},
             args=["case.prm", "--output-directory", "output"] + STUDY,
             exit=2, messages=["case.prm:1: not a text file (byte 0x7F"]),
        dict(name="working_directory_deleted", files=cup(),
             args=["{directory}/case.prm", "--output-directory",
                   "{directory}/output"],
             preexec=leave_working_directory, exit=2,
             messages=["the working directory cannot be read",
                       "was it deleted?"]),
    ]


def blank_file_cases():
    """Outline and Gmsh files: limits, scales, byte-order marks, cells that
    cannot make a hexahedron (D169, D175, D178)."""
    circle = "".join("%.9f %.9f\n" % (50 * math.cos(a * 2e-5 * math.pi),
                                        50 * math.sin(a * 2e-5 * math.pi))
                     for a in range(100000))
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    return [
        blank("polygon", "Outline file", "0 0\n" * 100001,
              "outline.txt:100001: more than the 100000 corners an outline "
              "may have", name="outline_too_many_corners"),
        blank("polygon", "Outline file", circle, exit=0,
              args=["--check", "case.prm"], name="outline_100000_corners"),
        blank("polygon", "Outline file", SQUARE.replace("60", "60e200"),
              "outline.txt:1: this corner lies 8.48528e+201 mm from the "
              "origin, more than the 10000 mm", name="outline_at_1e200_mm"),
        blank("polygon", "Outline file", SQUARE.replace("60", "60e-200"),
              "less than the 0.001 mm a blank must",
              name="outline_at_1e-200_mm"),
        blank("polygon", "Outline file", "\ufeff" + SQUARE, exit=0,
              args=["--check", "case.prm"], name="outline_byte_order_mark"),
        blank("gmsh", "Mesh file", "$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n"
              "$EndMeshFormat\n", "blank.msh:2: a binary Gmsh file",
              name="mesh_binary"),
        blank("gmsh", "Mesh file", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
              "$Nodes\n4000000000\n1 0 0 0\n$EndNodes\n",
              "blank.msh:5: the Nodes section announces 4000000000 entries, "
              "but only 2 lines follow", name="mesh_absurd_node_count"),
        blank("gmsh", "Mesh file", msh(square, [(1, 2, 4, 3)]),
              "blank.msh: cell 1 crosses itself (a bow-tie",
              name="mesh_bow_tie"),
        blank("gmsh", "Mesh file",
              msh([(0, 0), (10, 0), (3, 3), (0, 10)], [(1, 2, 3, 4)]),
              "blank.msh: cell 1 is not convex: its corner at (3, 3)",
              name="mesh_not_convex"),
    ]


def parameter_cases():
    """Holder forces that do not press (D176), draw-in names that break
    the CSV (D179), a locked output directory seen by --check and --study
    (D179)."""
    def locked(name, args):
        return holding_lock(dict(
            name=name, files=cup(), args=args, exit=2,
            messages=["'output' is in use by deepdraw process"]))
    return [
        dict(name="holder_force_zero",
             files=cup(sub("Process", "Blank holder force", "0")), exit=2,
             messages=["Process/Blank holder force = '0' gives 0 N at t = 0 "
                       "for the force-controlled tool 'blank holder'; "
                       "allowed are forces > 0 N"]),
        dict(name="holder_force_pulling",
             files=cup(sub("Process", "Blank holder force", "-4900")),
             exit=2, messages=["gives -4900 N at t = 0",
                               "allowed are forces > 0 N"]),
        dict(name="holder_force_reaching_zero",
             files=cup(sub("Process", "Blank holder force", "4900*(1-2*t)")),
             exit=2, messages=["gives 0 N at t = 0.5"]),
        dict(name="draw_in_name_with_comma",
             files=cup(sub("Process tables", "Draw-in points",
                           "A,B: 75, 0")), exit=2,
             messages=["Process tables/Draw-in points: the name 'A,B' has a "
                       "comma or a quote"]),
        locked("check_sees_lock",
               ["--check", "case.prm", "--output-directory", "output"]),
        holding_lock(dict(
            name="study_folder_locked", files=cup(),
            args=["case.prm", "--output-directory", "output"] + STUDY, exit=2,
            messages=["--study: 'output' is in use by deepdraw process"])),
    ]


def special_file_cases(source):
    return pipe_cases() + crash_cases() + blank_file_cases() + parameter_cases()
