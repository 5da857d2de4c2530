# pvpython: opens every VTU (or PVTU) part of OUTPUT_DIR/solution.pvd the way ParaView
# does and checks what a user colours by (doc/user_guide.md §3): the sheet's
# point fields present, finite and in plausible ranges; each tool with its
# normals. Exit code 1 with the reason otherwise.
#   pvpython --force-offscreen-rendering read_solution.py OUTPUT_DIR
import os
import sys
import xml.etree.ElementTree as ElementTree

from paraview import servermanager
from paraview.simple import XMLUnstructuredGridReader, PVDReader, \
    XMLPartitionedUnstructuredGridReader
from vtk.numpy_interface import dataset_adapter
import numpy

output = sys.argv[1]
pvd = os.path.join(output, "solution.pvd")

# (field, components, lowest, highest): ranges a short square-cup run must
# stay in; a NaN, an inf or a garbage value falls outside.
sheet_fields = [("displacement", 3, -5.0, 5.0),
                ("thickness_strain", 1, -0.5, 0.5),
                ("contact_status", 1, 0.0, 2.0),
                ("contact_gap", 1, -0.5, 2.0),
                ("contact_pressure", 1, -1e4, 1e4),
                ("friction_stress_x", 1, -1e4, 1e4),
                ("equivalent_stress", 1, 0.0, 1e3),
                ("equivalent_plastic_strain", 1, 0.0, 1.0),
                ("stress_xx", 1, -1e3, 1e3),
                ("rolling_direction_x", 1, -1.0, 1.0)]
problems = []


def arrays(reader):
    data = dataset_adapter.WrapDataObject(servermanager.Fetch(reader))
    return data, data.PointData


entries = list(ElementTree.parse(pvd).getroot().iter("DataSet"))
if not entries:
    sys.exit("no data set in " + pvd)
sheets = tools = 0
for entry in entries:
    name = entry.get("file")
    path = os.path.join(output, name)
    # A run under mpirun writes the sheet as a .pvtu record of one piece
    # per rank (D201).
    reader = XMLPartitionedUnstructuredGridReader(FileName=[path]) \
        if name.endswith(".pvtu") else XMLUnstructuredGridReader(FileName=[path])
    reader.UpdatePipeline()
    data, point_data = arrays(reader)
    points = numpy.asarray(data.Points)
    if points is None or len(points) == 0:
        problems.append("%s: ParaView read no points" % name)
        continue
    if not numpy.all(numpy.isfinite(points)):
        problems.append("%s: non-finite coordinates" % name)
    if name.startswith("solution-"):
        sheets += 1
        for field, components, low, high in sheet_fields:
            if field not in point_data.keys():
                problems.append("%s: no point field %s" % (name, field))
                continue
            values = numpy.asarray(point_data[field])
            shape = values.shape[1] if values.ndim == 2 else 1
            if shape != components:
                problems.append("%s: %s has %d components, expected %d"
                                % (name, field, shape, components))
            if not numpy.all(numpy.isfinite(values)):
                problems.append("%s: %s is not finite" % (name, field))
            elif values.min() < low or values.max() > high:
                problems.append("%s: %s in [%g, %g], expected within [%g, %g]"
                                % (name, field, values.min(), values.max(),
                                   low, high))
        print("  %s: %d points, fields ok" % (name, len(points)))
    else:
        tools += 1
        if "normal" not in point_data.keys():
            problems.append("%s: no point field normal" % name)
        else:
            normals = numpy.asarray(point_data["normal"])
            lengths = numpy.linalg.norm(normals, axis=1)
            if not numpy.all(numpy.isfinite(normals)) or \
                    numpy.any((lengths > 1e-12) & (abs(lengths - 1) > 1e-6)):
                problems.append("%s: normals not unit or not finite" % name)

# The collection as a whole, as File > Open solution.pvd does.
collection = PVDReader(FileName=pvd)
times = list(collection.TimestepValues)
if len(times) != sheets:
    problems.append("solution.pvd: %d time steps, %d sheet files"
                    % (len(times), sheets))
if tools != 3 * sheets:
    problems.append("%d tool files for %d steps, expected 3 per step"
                    % (tools, sheets))
for problem in problems:
    print("FAILED: " + problem)
print("%d sheet and %d tool files read, %d time steps %s"
      % (sheets, tools, len(times), times))
sys.exit(1 if problems else 0)
