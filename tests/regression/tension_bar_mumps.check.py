"""The tension-bar checks of tension_bar.check.py, for the MUMPS run."""
import pathlib
import runpy

runpy.run_path(str(pathlib.Path(__file__).with_name("tension_bar.check.py")),
               run_name="__main__")
