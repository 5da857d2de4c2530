"""Running deepdraw under mpirun for the tests of label parallel (D199):
oversubscribed (this machine has 2 cores and the tests run 3 ranks) and
allowed as root, as CI runs."""
import array
import base64
import os
import pathlib
import re
import struct
import subprocess
import sys
import zlib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import script_test  # noqa: E402,F401  (tests/script_test.py)

SHORT_CUP = (pathlib.Path(__file__).resolve().parent.parent / "restart"
             / "short_cup.prm")


def environment():
    env = dict(os.environ)
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    return env


def command(ranks, deepdraw, *arguments):
    """deepdraw's command line, under mpirun for ranks > 0 (0: without
    mpirun)."""
    launcher = ["mpirun", "--oversubscribe", "-np", str(ranks)] if ranks \
        else []
    return launcher + [str(deepdraw)] + [str(a) for a in arguments]


def run(ranks, deepdraw, work, *arguments, timeout=600):
    """Runs deepdraw with `ranks` ranks; returns (exit code, output)."""
    full = command(ranks, deepdraw, *arguments)
    print("running:", " ".join(full), flush=True)
    result = subprocess.run(full, cwd=work, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=timeout)
    print(result.stdout[-2000:], flush=True)
    return result.returncode, result.stdout


def start(ranks, deepdraw, work, *arguments):
    full = command(ranks, deepdraw, *arguments)
    print("starting:", " ".join(full), flush=True)
    return subprocess.Popen(full, cwd=work, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)


def newton_path(directory):
    """Per increment and iteration the columns that say which way Newton
    went: increment, load, iteration, contact changes."""
    rows = script_test.csv_rows(pathlib.Path(directory) / "newton.csv")
    return [(r["increment"], r["load"], r["iteration"], r["contact_changes"])
            for r in rows]


def _decode(text, dtype):
    """A binary DataArray of deal.II's VTU output: base64 of a zlib header
    (UInt32: blocks, block size, last block size, compressed sizes), then
    base64 of the compressed blocks."""
    text = text.strip()
    blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_length = 4 * (3 + blocks)
    header_chars = 4 * ((header_length + 2) // 3)
    header = struct.unpack("<%dI" % (3 + blocks),
                           base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    raw, at = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[at:at + size])
        at += size
    return array.array(dtype, raw)


def read_vtu(path):
    """(points as (x, y, z) tuples, {field: values per point}) of a VTU
    file or piece written by deepdraw (deal.II: every cell with its own
    copies of its vertices)."""
    codes = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B",
             "Int64": "q", "UInt32": "I"}
    text = pathlib.Path(path).read_text()
    points_xml = re.search(r"<Points>\s*<DataArray([^>]*)>([^<]*)</DataArray>",
                           text)
    kind = re.search(r'type="(\w+)"', points_xml.group(1)).group(1)
    flat = _decode(points_xml.group(2), codes[kind])
    points = [tuple(flat[i:i + 3]) for i in range(0, len(flat), 3)]
    fields = {}
    point_data = re.search(r"<PointData[^>]*>(.*?)</PointData>", text, re.S)
    for attributes, body in re.findall(r"<DataArray([^>]*)>([^<]*)</DataArray>",
                                       point_data.group(1) if point_data
                                       else ""):
        name = re.search(r'Name="([^"]+)"', attributes).group(1)
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        fields[name] = list(_decode(body, codes[kind]))
    return points, fields
