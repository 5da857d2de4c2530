"""The parameter files of the hostile-input cases (tests/input/
hostile_cases.py and the modules of its classes,
hostile_formability_cases.py and hostile_stage_cases.py): the coarse
square cup and the tension bar to add lines to, and subsections as text.
"""

# The square cup on 6 x 6 x 1 cells to t = 0.5 (tools, holder force, punch).
CUP = ("include prm/square_cup.prm\n"
       "subsection Geometry\n  set Elements along x = 6\n"
       "  set Elements along y = 6\n  set Layers through thickness = 1\nend\n"
       "subsection Process\n  set Final load = 0.5\nend\n")
# The tension bar (no tools), 22 increments to t = 1.
BAR = "include prm/tension_bar.prm\n"


def cup(*lines):
    return {"case.prm": CUP + "".join(line + "\n" for line in lines)}


def bar(*lines):
    return {"case.prm": BAR + "".join(line + "\n" for line in lines)}


def section(path, *entries):
    """'subsection A / subsection B ...' of path ("A/B") with entries, each
    (entry, value) or (subsection, entry, value), then as many 'end'."""
    parts = path.split("/")
    text = "".join("subsection %s\n" % p for p in parts)
    for entry in entries:
        if len(entry) == 3:
            text += "  subsection %s\n    set %s = %s\n  end\n" % entry
        else:
            text += "  set %s = %s\n" % entry
    return text + "end\n" * len(parts)


def sub(path, entry, value):
    """'subsection A / subsection B ... set entry = value ... end end'."""
    return section(path, (entry, value))
