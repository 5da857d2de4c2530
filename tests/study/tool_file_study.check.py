"""Checks the study of tool_file_study.prm: both runs done, each input.prm
names the tool files absolutely, and the force-controlled holder of each run
presses with the varied force (tools.csv of the run, last row)."""
import pathlib
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(pathlib.Path(__file__).parent))
from study_common import check, close, finish, read_study, read_table

output = pathlib.Path(sys.argv[1])
rows = read_study(output)
data = (pathlib.Path(__file__).parent.parent / "contact" / "data").resolve()
check("two rows", len(rows) == 2)
for k, (row, force) in enumerate(zip(rows, (30, 60))):
    folder = output / ("run_%d_%d" % (k + 1, force))
    check("%d N: status ok" % force, row["status"] == "ok", row["note"])
    text = (folder / "input.prm").read_text()
    for tool in ("flat_die.tool", "flat_holder.tool"):
        check("%d N: input.prm sets File = %s" % (force, data / tool),
              "set File = %s\n" % (data / tool) in text)
    tools = read_table(folder / "tools.csv")
    close("%d N: holder force" % force, abs(tools[-1]["holder_Fz"]), force, rel=1e-6)
finish()
