"""The checks of tiny_sheet.check.py for one_row_sheet.prm."""
import pathlib
import runpy

runpy.run_path(str(pathlib.Path(__file__).with_name("tiny_sheet.check.py")),
               run_name="__main__")
