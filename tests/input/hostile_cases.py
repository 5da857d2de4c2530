"""The cases of the hostile-input suite (run by run_hostile_inputs.py; the
numeric parameters are tests/input/hostile_parameters.cc). A case is a dict:

  name      unique within its class
  files     {relative path: str or bytes} written into the case directory
            (which also has the link prm -> the repository's prm/)
  args      deepdraw's arguments (default: case.prm --output-directory output)
  exit      the expected exit code
  messages  parts the message on stderr must contain
  output    the output directory to check (default "output")
  setup, cleanup, check, preexec: optional callables (see the runner)

Each class is a function of the repository root returning its cases.
"""
import os
import resource
import subprocess

from hostile_files_cases import special_file_cases
from hostile_formability_cases import formability_cases
from hostile_prm import BAR, CUP, bar, cup, sub
from hostile_stage_cases import stage, stage_and_output_cases


def files_cases(source):
    deep = {"case.prm": "include level1.prm\n"}
    for level in range(1, 21):
        deep["level%d.prm" % level] = "include level%d.prm\n" % (level + 1)
    deep["level21.prm"] = "# the bottom\n"
    bomb = {"case.prm": "include b.prm\n" * 40,
            "b.prm": "include c.prm\n" * 40, "c.prm": "# leaf\n"}

    def fifo(context):
        os.mkfifo(context["directory"] / "fifo.prm")

    def sparse(context):
        with open(context["directory"] / "huge.prm", "wb") as f:
            f.truncate(17 << 20)

    return [
        dict(name="self_include", files={"case.prm": "include case.prm\n"},
             exit=2, messages=["case.prm:1", "include cycle"]),
        dict(name="mutual_include",
             files={"case.prm": "# a\ninclude other.prm\n",
                    "other.prm": "include case.prm\n"},
             exit=2, messages=["include cycle", "case.prm:2", "other.prm:1"]),
        dict(name="include_cycle_through_a_path",
             files={"case.prm": "include sub/../case.prm\n", "sub/x": ""},
             exit=2, messages=["include cycle"]),
        dict(name="include_nested_too_deep", files=deep, exit=2,
             messages=["nested more than 16"]),
        dict(name="include_bomb", files=bomb, exit=2,
             messages=["more than 1000 include lines"]),
        dict(name="include_missing",
             files={"case.prm": CUP + "include nothing_here.prm\n"}, exit=2,
             messages=["nothing_here.prm", "cannot open the parameter file",
                       "included from case.prm:10"]),
        dict(name="include_directory",
             files={"case.prm": "include adir\n", "adir/x": ""}, exit=2,
             messages=["adir: is a directory"]),
        dict(name="include_device",
             files={"case.prm": "include /dev/zero\n"}, exit=2,
             messages=["/dev/zero: is a character device, not a regular "
                       "file"]),
        dict(name="include_binary",
             files={"case.prm": "include blob.prm\n",
                    "blob.prm": bytes(range(256)) * 4}, exit=2,
             messages=["blob.prm:1: not a text file", "included from"]),
        dict(name="include_byte_order_mark",
             files={"case.prm": CUP + "include bom.prm\n",
                    "bom.prm": "\ufeff# saved by a Windows editor\n"},
             exit=2,
             messages=["bom.prm: begins with a UTF-8 byte-order mark",
                       "included from case.prm:10"]),
        dict(name="prm_is_a_directory", files={"dir.prm/x": ""},
             args=["dir.prm"], exit=2,
             messages=["dir.prm: is a directory, not a parameter file"]),
        dict(name="prm_missing", args=["missing.prm"], exit=2,
             messages=["missing.prm: cannot open the parameter file"]),
        dict(name="prm_binary",
             files={"case.prm": b"\x7fELF\x02\x01\x01\x00" + bytes(range(256))},
             exit=2, messages=["case.prm:1: not a text file (byte 0x7F"]),
        dict(name="prm_escape_sequences",
             files={"case.prm": "subsection Geometry\n  set Length = \x1b[2J75\n"
                                "end\n"},
             exit=2, messages=["case.prm:2: not a text file (byte 0x1B"]),
        dict(name="prm_latin1_comment",
             files={"case.prm": b"# r\xe9sum\xe9\n" + BAR.encode()}, exit=2,
             messages=["case.prm:1: not a text file (byte 0xE9"]),
        dict(name="prm_fifo", setup=fifo, args=["fifo.prm"], exit=2,
             messages=["fifo.prm: is a named pipe, not a regular file"]),
        dict(name="prm_too_large", setup=sparse, args=["huge.prm"], exit=2,
             messages=["more than the 16 MB"]),
        dict(name="prm_dev_null", args=["/dev/null"], exit=2,
             messages=["/dev/null: is a character device, not a regular "
                       "file"]),
        dict(name="prm_not_prm_ending", files={"case.txt": BAR},
             args=["case.txt"], exit=2, messages=["must end in .prm"]),
        dict(name="multiple_run_braces",
             files=bar(sub("Geometry", "Length", "{10|20}")), exit=2,
             messages=["case.prm:3", "'{'"]),
        dict(name="unbalanced_subsection",
             files={"case.prm": "subsection Geometry\n  set Length = 10\n"},
             exit=2, messages=["case.prm"]),
        dict(name="end_without_subsection", files={"case.prm": "end\n"},
             exit=2, messages=["There is no subsection to leave here"]),
        dict(name="unknown_subsection",
             files={"case.prm": "subsection Geometri\nend\n"}, exit=2,
             messages=["Geometri"]),
        dict(name="garbage_line",
             files={"case.prm": "this is not a prm line\n"}, exit=2,
             messages=["could not be parsed"]),
        dict(name="continuation_into_include_cycle",
             files={"case.prm": "inc\\\nlude case.prm\n"}, exit=2,
             messages=["include cycle"]),
    ]


def command_line_cases(source):
    return [
        dict(name="no_arguments", args=[], exit=1,
             messages=["no parameter file given", "usage:"]),
        dict(name="output_directory_without_value", files=bar(),
             args=["case.prm", "--output-directory"], exit=1,
             messages=["--output-directory needs a directory name"]),
        dict(name="output_directory_empty", files=bar(),
             args=["case.prm", "--output-directory", ""], exit=1,
             messages=["--output-directory needs a directory name"]),
        dict(name="output_directory_twice", files=bar(),
             args=["case.prm", "--output-directory", "a",
                   "--output-directory", "b"], exit=1,
             messages=["--output-directory given twice"]),
        dict(name="unknown_option", files=bar(), args=["case.prm", "--fast"],
             exit=1, messages=["unknown argument '--fast'"]),
        dict(name="two_parameter_files", files=bar(),
             args=["case.prm", "other.prm"], exit=1,
             messages=["more than one parameter file"]),
        dict(name="output_directory_is_a_file",
             files=dict(bar(), **{"taken": "x"}),
             args=["case.prm", "--output-directory", "taken"], exit=2,
             output="", messages=["Output/Output directory",
                                  "cannot write results to 'taken'"],
             check=lambda c: [] if (c["directory"] / "taken").read_text() == "x"
             else ["the file given as output directory was changed"]),
        dict(name="output_directory_cannot_be_made", files=bar(),
             args=["case.prm", "--output-directory", "/proc/deepdraw/out"],
             exit=2, output="",
             messages=["cannot write results to '/proc/deepdraw/out'"]),
        # --check finds both without making anything (issue 32 item 8).
        dict(name="check_output_directory_is_a_file",
             files=dict(bar(), **{"taken": "x"}),
             args=["--check", "case.prm", "--output-directory", "taken"],
             exit=2, output="", messages=["Output/Output directory",
                                          "cannot write results to 'taken'",
                                          "is not a directory"]),
        dict(name="check_output_directory_cannot_be_made", files=bar(),
             args=["--check", "case.prm", "--output-directory",
                   "/proc/deepdraw/out"],
             exit=2, output="",
             messages=["cannot write results to '/proc/deepdraw/out'"]),
        dict(name="check_of_bad_input",
             files=bar(sub("Geometry", "Length", "-1")),
             args=["--check", "case.prm"], exit=2, messages=["Length"]),
        dict(name="check_of_good_input", files=cup(),
             args=["--check", "case.prm"], exit=0,
             messages=[], check=lambda c: [] if not (c["directory"] / "output-square-cup").exists()
             else ["--check wrote output"]),
    ]


def expression_cases(source):
    tool1 = "Contact/Tool 1"
    return [
        dict(name="holder_force_syntax",
             files=cup(sub("Process", "Blank holder force", "4900*(")), exit=2,
             messages=["Process/Blank holder force = '4900*('",
                       "Unexpected end of expression"]),
        dict(name="boundary_condition_syntax",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmax: ux = sin(")), exit=2,
             messages=["Prescribed displacements", "xmax: ux = sin("]),
        dict(name="boundary_condition_unknown_variable",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmax: ux = q*t")), exit=2,
             messages=["Prescribed displacements", "variables: x, y, z, t"]),
        dict(name="boundary_condition_sqrt_of_negative",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmax: ux = sqrt(-1)*t")), exit=2,
             messages=["'xmax: ux = sqrt(-1)*t' gives -nan at t = 0"]),
        dict(name="boundary_condition_pole_inside_the_run",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "zmin: uz = 0; xmax: ux = 1/(t-0.5)")), exit=2,
             messages=["'xmax: ux = 1/(t-0.5)' gives inf at t = 0.5"]),
        dict(name="boundary_condition_no_value_beyond_half",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "zmin: uz = 0; xmax: ux = sqrt(0.5-t)")), exit=2,
             messages=["gives -nan at t = 0.6"]),
        dict(name="boundary_condition_huge",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmax: ux = 1e300*t")), exit=2,
             messages=["allowed are finite displacements up to 1000 mm"]),
        dict(name="boundary_condition_unknown_face",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmid: ux = 0")), exit=2,
             messages=["unknown face 'xmid'"]),
        dict(name="boundary_condition_without_equals",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "xmax ux 0")), exit=2,
             messages=["expected 'FACE: COMPONENT = EXPRESSION'"]),
        dict(name="translation_division_by_zero",
             files=cup(sub(tool1, "Translation", "0; 0; -t/0")), exit=2,
             messages=["Contact/Tool 1/Translation = '0; 0; -t/0' gives uz",
                       "at t = 0"]),
        dict(name="translation_pole_inside_the_run",
             files=cup(sub(tool1, "Translation", "0; 0; 1/(t-0.25)")), exit=2,
             messages=["gives uz = inf mm at t = 0.25"]),
        dict(name="translation_two_components",
             files=cup(sub(tool1, "Translation", "0; -t")), exit=2,
             messages=["expected 3 expression(s)"]),
        dict(name="translation_huge",
             files=cup(sub(tool1, "Translation", "0; 0; -1e300*t")), exit=2,
             messages=["allowed are finite translations up to"]),
        dict(name="holder_force_huge",
             files=cup(sub("Process", "Blank holder force", "1e300")), exit=2,
             messages=["allowed are finite forces up to 1e+09 N"]),
        dict(name="holder_force_pole_at_the_end",
             files=cup(sub("Process", "Blank holder force", "4900/(t-0.5)")),
             exit=2, messages=["gives inf N at t = 0.5"]),
        dict(name="force_direction_zero",
             files=cup(sub("Contact/Tool 3", "Force direction", "0, 0, 0")),
             exit=2, messages=["the direction must not be zero"]),
        dict(name="force_direction_overflowing",
             files=cup(sub("Contact/Tool 3", "Force direction",
                           "1e300, 1e300, -1e300")), exit=0,
             args=["--check", "case.prm"]),
        dict(name="force_direction_not_a_number",
             files=cup(sub("Contact/Tool 3", "Force direction", "nan, 0, 1")),
             exit=2, messages=["expected three finite numbers"]),
        dict(name="draw_in_point_not_finite",
             files=cup(sub("Process tables", "Draw-in points", "DX: 1e999, 0")),
             exit=2, messages=["'1e999' is not a number"]),
        dict(name="tool_name_with_comma",
             files=cup(sub(tool1, "Name", "punch, left")), exit=2,
             messages=["must not contain commas"]),
        dict(name="tool_name_with_slash",
             files=cup(sub(tool1, "Name", "../punch")), exit=2,
             messages=["slashes"]),
        dict(name="tool_names_equal",
             files=cup(sub("Contact/Tool 2", "Name", "punch")), exit=2,
             messages=["Contact/Tool 2/Name = 'punch'",
                       "tool names must differ"]),
        dict(name="thickness_travels_one_file_name",
             files=cup(sub("Output", "Thickness profile travels",
                           "0.25, 0.2500000000001")), exit=2,
             messages=["both give the file name thickness_OX_0.25mm.csv"]),
        dict(name="search_distance_beyond_the_blank",
             files=cup(sub("Contact", "Search distance", "5000")), exit=2,
             messages=["Contact/Search distance = 5000 mm is larger than the "
                       "blank"]),
        dict(name="output_interval_tiny",
             files=cup(sub("Output", "Output interval", "1e-300")), exit=2,
             messages=["Output/Output interval = 1e-300 would write"]),
        dict(name="mesh_too_large_for_the_memory",
             files=cup(sub("Geometry", "Elements along x", "100000")), exit=2,
             messages=["cells with 3 tool(s) needs about", "GB available"]),
        # With more than 2 points through the thickness the message names
        # them and the parameter that shrinks the estimate (D203; the
        # estimate's growth itself is the measurement there).
        dict(name="mesh_with_4_points_too_large_for_the_memory",
             files=cup(sub("Geometry", "Elements along x", "100000"),
                       sub("Finite element", "Points through the thickness",
                           "4")), exit=2,
             messages=["cells with 3 tool(s) and 4 points through the "
                       "thickness needs about",
                       "or Finite element/Points through the thickness"]),
    ]


FLAT_DIE_PATCH = ("patch\ndegrees 1 1\n-10 -10 0 1\n20 -10 0 1\n"
                  "-10 20 0 1\n20 20 0 1\nend\n")
TOOL_PRM = ("subsection Geometry\n  set Length = 2\n  set Width = 2\n"
            "  set Thickness = 0.5\n  set Elements along x = 2\n"
            "  set Elements along y = 2\n  set Layers through thickness = 1\n"
            "end\nsubsection Boundary conditions\n"
            "  set Prescribed displacements = zmax: uz = -0.01*t\nend\n"
            "subsection Contact\n  subsection Tool 1\n    set Name = die\n"
            "    set File = data/die.tool\n    set Sheet surface = bottom\n"
            "  end\nend\n")


def tool(name, content, *messages):
    return dict(name=name, files={"case.prm": TOOL_PRM, "data/die.tool": content},
                exit=2, messages=list(messages))


def tool_file_cases(source):
    def patch(points, degrees="1 1"):
        return "patch\ndegrees %s\n%send\n" % (degrees, points)

    square = "0 0 0 1\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"
    return [
        dict(name="valid_flat_die", files={"case.prm": TOOL_PRM,
                                           "data/die.tool": FLAT_DIE_PATCH},
             args=["--check", "case.prm"], exit=0),
        tool("not_a_number", patch("0 0 0 1\n1.0 abc 2 1\n0 1 0 1\n1 1 0 1\n"),
             "data/die.tool:4: expected 3 coordinates and a weight, found "
             "\"1.0 abc 2 1\""),
        tool("three_numbers", patch("0 0 0\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "die.tool:3: expected 3 coordinates and a weight"),
        tool("weight_zero", patch("0 0 0 0\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "die.tool:3: weights must be positive, found 0"),
        tool("weight_negative", patch("0 0 0 -1\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "weights must be positive"),
        tool("weight_tiny", patch(square.replace(" 1\n", " 1e-300\n")),
             "weights must lie between 1e-6 and 1e6, found 1e-300"),
        tool("weight_huge", patch(square.replace(" 1\n", " 1e300\n")),
             "weights must lie between 1e-6 and 1e6"),
        tool("coordinate_huge", patch("0 0 0 1\n1e300 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "coordinates must lie within +-1e6 mm"),
        tool("not_finite", patch("nan 0 0 1\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "expected finite numbers"),
        tool("infinite", patch("inf 0 0 1\n1 0 0 1\n0 1 0 1\n1 1 0 1\n"),
             "expected finite numbers"),
        tool("too_few_points", patch(square, "3 3"),
             "degrees 3 3 need 16 control points (4 x 4), found 4"),
        tool("one_point_too_many", patch(square + "2 2 0 1\n"),
             "degrees 1 1 need 4 control points; this is one more"),
        tool("degree_above_maximum", patch(square, "40 1"),
             "degrees above the maximum 15, found \"degrees 40 1\""),
        tool("degree_zero", patch(square, "0 1"), "degrees must be at least 1"),
        tool("degree_not_integer", patch(square, "1.5 1"),
             "expected two degrees (integers)"),
        tool("degree_overflowing", patch(square, "99999999999 1"),
             "expected two degrees (integers)"),
        tool("degrees_twice", "patch\ndegrees 1 1\ndegrees 1 1\n" + square + "end\n",
             "'degrees' given twice"),
        tool("point_before_degrees", "patch\n0 0 0 1\ndegrees 1 1\nend\n",
             "control point before the patch's 'degrees' line"),
        tool("no_degrees", "patch\nend\n", "has no 'degrees'"),
        tool("no_end", "patch\ndegrees 1 1\n" + square,
             "the patch started at line 1 has no 'end'"),
        tool("patch_inside_patch", "patch\ndegrees 1 1\n" + square + "patch\n",
             "has no 'end' before this 'patch'"),
        tool("text_after_end", "patch\ndegrees 1 1\n" + square + "end now\n",
             "expected nothing after 'end'"),
        tool("text_after_patch", "patch 1\n", "expected nothing after 'patch'"),
        tool("unknown_keyword", "patchy\n", "expected 'tool' or 'patch'"),
        tool("misspelt_edge_kind",
             "patch\ndegrees 1 1\n" + square + "edges auto free free free\nend\n",
             "expected 'edges' and four of automatic, free, shared, symmetry"),
        tool("edges_twice",
             "patch\ndegrees 1 1\n" + square + "edges free free free free\n"
             "edges free free free free\nend\n", "'edges' given twice"),
        tool("no_patch", "# nothing but a comment\n", "no patch in the tool file"),
        tool("empty_file", "", "no patch in the tool file"),
        tool("tool_after_patch", FLAT_DIE_PATCH + "tool late\n",
             "'tool' must appear once, before the first patch"),
        tool("tool_without_name", "tool\n" + FLAT_DIE_PATCH,
             "expected a tool name after 'tool'"),
        tool("degenerate_all_points_equal",
             patch("1 1 1 1\n1 1 1 1\n1 1 1 1\n1 1 1 1\n"),
             "die.tool:7: the patch started at line 1 is degenerate: all its "
             "control points are equal"),
        tool("degenerate_points_on_a_line",
             patch("0 0 0 1\n1 0 0 1\n2 0 0 1\n3 0 0 1\n"),
             "is degenerate: x_u x x_v = 0"),
        tool("degenerate_folded_net",
             patch("0 0 0 1\n1 0 0 1\n1 0 0 1\n0 0 0 1\n"),
             "is degenerate"),
        tool("degenerate_folded_over",
             patch("0 0 0 1\n2 0 0 1\n1 0 0 1\n0 1 0 1\n2 1 0 1\n1 1 0 1\n",
                   "2 1"),
             "is degenerate: its normal x_u x x_v flips between",
             "the patch folds over onto itself"),
        tool("degenerate_collapsed_corner",
             patch("0 0 0 1\n1 0 0 1\n0 1 0 1\n0 1 0 1\n"),
             "is degenerate: x_u x x_v = 0 at (u, v) = (0, 1), a collapsed "
             "edge or corner"),
        tool("degenerate_tiny", patch(square.replace("1 ", "1e-12 ")),
             "is degenerate: all its control points are equal"),
        tool("binary", bytes(range(256)), "die.tool:1: not a text file"),
        dict(name="directory", files={"case.prm": TOOL_PRM, "data/die.tool/x": ""},
             exit=2, messages=["die.tool: is a directory, not a tool file"]),
        dict(name="missing", files={"case.prm": TOOL_PRM}, exit=2,
             messages=["Contact/Tool 1/File: cannot open the tool file"]),
        dict(name="long_line",
             files={"case.prm": TOOL_PRM, "data/die.tool": "x" * 100000 + "\n"},
             exit=2, messages=["expected 'tool' or 'patch'", "..."]),
    ]


def run_time_cases(source):
    """Failures after the output has started: exit code 3."""
    def mount(context, size):
        if os.geteuid() != 0:
            return "a tiny tmpfs needs root"
        full = context["directory"] / "full"
        full.mkdir()
        if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs",
                           str(full)], capture_output=True).returncode != 0:
            return "mount -t tmpfs is not allowed here"
        return None

    def umount(context):
        # What the run left on the tmpfs is kept on the real disk, in the
        # same place, for the checks.
        full = context["directory"] / "full"
        copy = context["directory"] / "full_copy"
        if os.path.ismount(full):
            subprocess.run(["cp", "-a", str(full), str(copy)])
            subprocess.run(["umount", str(full)])
            os.rmdir(full)
            os.rename(copy, full)

    return [
        dict(name="disk_full_while_writing_a_vtu", files=bar(),
             setup=lambda c: mount(c, "48k"), cleanup=umount,
             args=["case.prm", "--output-directory", "full/out"],
             output="full/out", exit=3,
             messages=["the run stopped: no space left on device while "
                       "writing full/out/solution-"],
             # Under mpirun the sheet is written in pieces (D201): the disk
             # may fill on a piece, its .pvtu record or solution.pvd.
             launcher_messages=["the run stopped: no space left on device "
                                "while writing full/out/solution"]),
        dict(name="disk_full_while_writing_a_csv_row",
             files=bar(sub("Output", "Write VTU", "false")),
             setup=lambda c: mount(c, "12k"), cleanup=umount,
             args=["case.prm", "--output-directory", "full/out"],
             output="full/out", exit=3,
             messages=["the run stopped: no space left on device while "
                       "writing full/out/", ".csv"]),
        dict(name="disk_full_before_the_first_increment",
             files=bar(sub("Output", "Write VTU", "false")),
             setup=lambda c: mount(c, "8k"), cleanup=umount,
             args=["case.prm", "--output-directory", "full/out"],
             output="full/out", exit=2,
             messages=["Output/Output directory: cannot write results to "
                       "'full/out': no space left on device while writing "
                       "full/out/"]),
        dict(name="boundary_condition_without_value_between_check_loads",
             files=bar(sub("Boundary conditions", "Prescribed displacements",
                           "zmin: uz = 0; xmax: ux = sqrt(abs(t-0.55)-0.01)")),
             exit=3,
             messages=["Boundary conditions/Prescribed displacements: "
                       "'xmax: ux = sqrt(abs(t-0.55)-0.01)' is not finite at "
                       "t = 0.5"]),
        # D177: 1950 MiB of address space hold the 100 x 100 x 2 cup's
        # set-up, MUMPS' analysis and the checkpoint, not the 0.87 GB more
        # of its factorisation (VmPeak 2.36 GB without a limit): measured,
        # the run stops in MUMPS with a checkpoint from 1800 to 2100 MiB.
        dict(name="mumps_out_of_memory",
             files={"case.prm": "include prm/square_cup.prm\n" + sub(
                 "Geometry", "Elements along x", "100") + sub(
                 "Geometry", "Elements along y", "100") + sub(
                 "Process", "Final load", "0.1") + sub(
                 "Output", "Write VTU", "false")},
             preexec=lambda: resource.setrlimit(
                 resource.RLIMIT_AS, (1950 << 20, 1950 << 20)),
             exit=3,
             messages=["the run stopped: the linear solver MUMPS ran out of "
                       "memory in job 2", "a smaller increment would not "
                       "help", "with a checkpoint to continue from"]),
        dict(name="holder_force_zero_between_check_loads",
             files=cup(sub("Process", "Blank holder force",
                           "if(t > 0.101 && t < 0.149, 0, 4900)")),
             exit=3,
             messages=["the run stopped: Process/Blank holder force = "
                       "'if(t > 0.101 && t < 0.149, 0, 4900)' gives 0 N at "
                       "t = 0.1125; a force-controlled tool needs a force "
                       "> 0 N"]),
        dict(name="release_supports_find_one_node",
             files=bar(sub("Geometry", "Symmetry planes", ""),
                       sub("Boundary conditions", "Prescribed displacements",
                           "xmin: ux = 0; ymin: uy = 0; zmin: uz = 0; "
                           "xmax: ux = 10*(exp(0.5*t)-1)"),
                       sub("Output", "Write VTU", "false"),
                       stage(1, ("Name", "stretch"), ("Final load", "0.2")),
                       stage(2, ("Name", "springback"), ("Kind", "release"),
                             ("Prescribed displacements", "none"),
                             ("Release supports",
                              "point(0, 0, 0): ux uy uz; point(0.01, 0, 0): "
                              "uy uz; point(0, 0.01, 0): uz"))),
             exit=3,
             messages=["stage 2 'springback' cannot begin: Process/Stage "
                       "2/Release supports: at the nodes found the released "
                       "sheet is free to move (rotation about"]),
    ]


def msh(nodes, elements):
    """A Gmsh 2.2 file; elements are (type, node numbers): 3 quadrangle,
    2 triangle."""
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes",
             str(len(nodes))]
    lines += ["%d %g %g 0" % (k + 1, x, y) for k, (x, y) in enumerate(nodes)]
    lines += ["$EndNodes", "$Elements", str(len(elements))]
    lines += ["%d %d 2 1 1 %s" % (k + 1, kind, " ".join(map(str, n)))
              for k, (kind, n) in enumerate(elements)]
    return "\n".join(lines + ["$EndElements"]) + "\n"


def blank_file_cases(source):
    """Outline and mesh files of Geometry/Blank outline (doc/user_guide.md
    §2.1): each rejected naming the file (and line or cell), exit code 2."""
    def blank(outline, entry, path, content, messages, name):
        return dict(name=name, files={
            "case.prm": CUP + sub("Geometry", "Blank outline", outline)
            + sub("Geometry", entry, path), path: content}, exit=2,
            messages=[path.split("/")[-1]] + list(messages))

    def polygon(content, *messages, name):
        return blank("polygon", "Outline file", "data/outline.txt", content,
                     messages, name)

    def gmsh(content, *messages, name):
        return blank("gmsh", "Mesh file", "data/blank.msh", content, messages,
                     name)

    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    return [
        dict(name="valid_polygon", files={
            "case.prm": CUP + sub("Geometry", "Blank outline", "polygon")
            + sub("Geometry", "Outline file", "data/outline.txt"),
            "data/outline.txt": "# square\n-60 -60\n60 -60\n60 60\n"
                                "-60 60\n"}, args=["--check", "case.prm"],
             exit=0),
        dict(name="outline_file_missing", files={
            "case.prm": CUP + sub("Geometry", "Blank outline", "polygon")
            + sub("Geometry", "Outline file", "data/none.txt")}, exit=2,
             messages=["none.txt"]),
        dict(name="outline_file_not_given", files={
            "case.prm": CUP + sub("Geometry", "Blank outline", "polygon")},
             exit=2, messages=["Geometry/Outline file is empty"]),
        polygon("0 -1\n1 abc\n", "outline.txt:2: expected two numbers",
                name="outline_not_a_number"),
        polygon("-1 -1\n1 1\n", "at least three points",
                name="outline_two_points"),
        polygon("-1 -1\n1 -1\n1 -1\n1 1\n", "outline.txt:3: the point "
                "repeats", name="outline_repeated_point"),
        polygon("-1 -1\n1 1\n1 -1\n-1 1\n", "outline.txt:3:",
                "intersects itself", name="outline_self_intersecting"),
        polygon("1 1\n2 1\n2 2\n1 2\n", "not star-shaped about the origin",
                name="outline_origin_outside"),
        dict(name="mesh_file_missing", files={
            "case.prm": CUP + sub("Geometry", "Blank outline", "gmsh")
            + sub("Geometry", "Mesh file", "data/none.msh")}, exit=2,
             messages=["none.msh", "cannot open the mesh file"]),
        gmsh("this is not a mesh\n", "not a usable two-dimensional Gmsh mesh",
             name="mesh_not_msh"),
        gmsh(msh(square, [(2, [1, 2, 3]), (2, [1, 3, 4])]),
             "cell 1 is not a quadrilateral", name="mesh_of_triangles"),
        gmsh(msh([(-10, 0), (0, 0), (0, 10), (-10, 10)], [(3, [1, 2, 3, 4])]),
             "far side of a symmetry plane", name="mesh_beyond_symmetry_plane"),
    ]


CLASSES = {"stages_and_outputs": stage_and_output_cases,
           "formability": formability_cases,
           "files": files_cases, "command_line": command_line_cases,
           "expressions": expression_cases, "tool_files": tool_file_cases,
           "run_time": run_time_cases, "blank_files": blank_file_cases,
           "special_files": special_file_cases}
