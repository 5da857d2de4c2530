# Picture of a deepdraw run at one punch travel: the sheet coloured by its
# thickness strain (or another field), the tools translucent, isometric
# view, white background.
#   pvpython --force-offscreen-rendering scripts/render_square_cup.py \
#       OUTPUT_DIR PNG_FILE [TRAVEL [FIELD [WIDTH]]]
# (scripts/render_square_cup.sh finds pvpython and a virtual X server.)
# TRAVEL is the pvd time (punch travel in mm); default: the last step.
# FIELD: thickness_strain (default, a point field), or flc_margin: the least
# of the cell fields flc_margin_bottom, _mid, _top of the post-processor
# "forming limits" (doc/user_guide.md §8.2). WIDTH: of the picture in
# pixels (default 1600; the height is 5/8 of it, the fonts scale with it).
# A quarter model (sheet touching x = 0 and y = 0 from the positive side) is
# mirrored about both planes so that the whole cup is seen.
import os
import sys
import xml.etree.ElementTree as ElementTree

from paraview.simple import *  # noqa: F401,F403  (the pvpython idiom)

if len(sys.argv) not in (3, 4, 5, 6):
    sys.exit("usage: render_square_cup.py OUTPUT_DIR PNG_FILE "
             "[TRAVEL [FIELD [WIDTH]]]")
output_dir, png_file = sys.argv[1], sys.argv[2]
field = sys.argv[4] if len(sys.argv) >= 5 else "thickness_strain"
try:
    width = int(sys.argv[5]) if len(sys.argv) == 6 else 1600
except ValueError:
    width = 0
if not 100 <= width <= 8000:
    sys.exit("render: WIDTH must be a number of pixels from 100 to 8000")
# The colour bar's title of each field; low values are red in both (thinning,
# little margin left).
titles = {"thickness_strain": "thickness strain ln(t/t0)",
          "flc_margin": "margin to the FLC, eps1*(eps2) - eps1\n"
                        "(least of bottom, mid, top)"}
if field not in titles:
    sys.exit("render: FIELD must be one of %s, not '%s'"
             % (", ".join(sorted(titles)), field))
pvd = os.path.join(output_dir, "solution.pvd")
if not os.path.isfile(pvd):
    sys.exit("render: no %s" % pvd)

# The pvd is read by hand rather than with PVDReader: the reader gives the
# parts as unnamed blocks, whereas the file names tell the sheet
# (solution-NNNNN.vtu) from each tool (tool_<name>-NNNNN.vtu). A step is the
# run of entries starting at part 0.
steps = []  # (time, [files])
for entry in ElementTree.parse(pvd).getroot().iter("DataSet"):
    if entry.get("part", "0") == "0" or not steps:
        steps.append((float(entry.get("timestep")), []))
    steps[-1][1].append(entry.get("file"))
if not steps:
    sys.exit("render: %s lists no data set" % pvd)
if len(sys.argv) >= 4:
    try:
        travel = float(sys.argv[3])
    except ValueError:
        sys.exit("render: TRAVEL must be a number (mm), not '%s'" % sys.argv[3])
    # The nearest step; the last one if a travel was written twice.
    time, files = min(reversed(steps), key=lambda s: abs(s[0] - travel))
    if abs(time - travel) > 1e-6 * max(1.0, abs(travel)):
        print("render: no step at travel %g mm, using the nearest, %g mm "
              "(available: %s)" % (travel, time,
                                   " ".join("%g" % s[0] for s in steps)))
else:
    time, files = steps[-1]
sheets = [f for f in files if os.path.basename(f).startswith("solution")]
if not sheets:
    sys.exit("render: no solution-NNNNN.vtu at travel %g mm in %s" % (time, pvd))
sheet_file = sheets[0]
# A tool file that has gone (cleaned output) only costs its picture.
tool_files = [f for f in files if f != sheet_file
              and os.path.isfile(os.path.join(output_dir, f))]
print("render: travel %g mm, %s + %d tool(s)" % (time, sheet_file, len(tool_files)))


def read(name):
    path = name if os.path.isabs(name) else os.path.join(output_dir, name)
    return XMLUnstructuredGridReader(FileName=[path])


def mirrored(source, about_x, about_y):
    """source reflected about x = 0 and/or y = 0, keeping the original."""
    if about_x:
        source = Reflect(Input=source, Plane="X", CopyInput=1)
    if about_y:
        source = Reflect(Input=source, Plane="Y", CopyInput=1)
    return source


# The vertices of the VTU are the current (moved) configuration (updated
# Lagrangian), so no WarpByVector is needed.
sheet = read(sheet_file)
sheet.UpdatePipeline()
# deal.II writes a cell field at the vertices of each cell (its patch), so
# it arrives as point data, constant over each cell.
if field == "flc_margin":
    surfaces = ["flc_margin_%s" % s for s in ("bottom", "mid", "top")]
    missing = [a for a in surfaces if a not in sheet.PointData.keys()]
    if missing:
        sys.exit("render: %s has no field %s (VTU field 'flc margin' of the "
                 "post-processor 'forming limits')"
                 % (sheet_file, ", ".join(missing)))
    # min(a, b) = (a + b - |a - b|)/2: the calculator's min is a reduction.
    pair = "(%s + %s - abs(%s - %s)) / 2"
    lower = pair % (surfaces[0], surfaces[1], surfaces[0], surfaces[1])
    sheet = PythonCalculator(Input=sheet, ArrayAssociation="Point Data",
                             ArrayName=field,
                             Expression=pair % (lower, surfaces[2], lower,
                                                surfaces[2]))
    sheet.UpdatePipeline()
elif field not in sheet.PointData.keys():
    sys.exit("render: %s has no point field %s (fields: %s)"
             % (sheet_file, field, ", ".join(sheet.PointData.keys())))
xmin, xmax, ymin, ymax, zmin, zmax = sheet.GetDataInformation().GetBounds()
tolerance = 1e-6 * max(xmax - xmin, ymax - ymin, 1.0)
mirror_x, mirror_y = abs(xmin) < tolerance, abs(ymin) < tolerance

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [width, width * 5 // 8]
# Fonts and lines in proportion to the picture (drawn for 1600 pixels).
zoom = width / 1600.0
view.Background = [1, 1, 1]
if hasattr(view, "UseColorPaletteForBackground"):  # ParaView >= 5.10
    view.UseColorPaletteForBackground = 0
view.OrientationAxesVisibility = 1
view.OrientationAxesLabelColor = [0, 0, 0]

whole_sheet = mirrored(sheet, mirror_x, mirror_y)
display = Show(whole_sheet, view)
display.SetRepresentationType("Surface With Edges")
display.EdgeColor = [0.25, 0.25, 0.25]
ColorBy(display, ("POINTS", field))
lut = GetColorTransferFunction(field)
# Thinning (negative, where the cup fails) in red; a rainbow without dark
# ends keeps the small strains of the bottom and the flange readable.
if not lut.ApplyPreset("Rainbow Uniform", True):
    lut.ApplyPreset("Jet", True)
lut.InvertTransferFunction()
low, high = sheet.PointData[field].GetRange()
if high - low < 1e-12:  # a flat field still needs a usable bar
    low, high = low - 1e-3, high + 1e-3
lut.RescaleTransferFunction(low, high)
bar = GetScalarBar(lut, view)
bar.Title = titles[field]
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.TitleFontSize = bar.LabelFontSize = max(8, round(20 * zoom))
bar.RangeLabelFormat = "%-#.3g"
bar.ScalarBarLength = 0.5
bar.WindowLocation = "Any Location"
bar.Position = [0.88, 0.25]
bar.Visibility = 1

# Tools translucent grey, each a slightly different shade; a tool lying on
# the positive side only (a quarter tool) is mirrored like the sheet. Tools
# are cut to the sheet's bounding box (+5 %): the die and holder planes and
# the punch walls reach far beyond it and would grey the whole picture.
bounds = whole_sheet.GetDataInformation().GetBounds()
look = [-1 / 3 ** 0.5, 1 / 3 ** 0.5, -1 / 3 ** 0.5]  # camera direction, below
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
margin = 0.05 * max(bounds[1] - bounds[0], bounds[3] - bounds[2])
for k, name in enumerate(sorted(tool_files)):
    tool = read(name)
    tool.UpdatePipeline()
    txmin, _, tymin, _, _, _ = tool.GetDataInformation().GetBounds()
    tool = mirrored(tool, mirror_x and txmin > -tolerance,
                    mirror_y and tymin > -tolerance)
    # Merged points (patches and mirrored copies share their edges), so that
    # the boundary edges drawn below are the tool's outline only. The
    # tolerance (2e-3 of the sheet, 0.3 mm for the cup) also closes the seams
    # where patch tessellations do not match (punch-corner patches).
    tool = CleantoGrid(Input=tool, ToleranceIsAbsolute=1,
                       AbsoluteTolerance=2e-3 * size)
    tool = Clip(Input=tool, ClipType="Box")
    tool.ClipType.Position = [bounds[2 * d] - margin for d in range(3)]
    tool.ClipType.Length = [bounds[2 * d + 1] - bounds[2 * d] + 2 * margin
                            for d in range(3)]
    tool.Invert = 1  # keep the inside of the box
    if hasattr(tool, "Exact"):
        tool.Exact = 1  # straight cut edges
    # A tool touching the sheet z-fights with it (stripes). Moving it towards
    # the camera along the view direction changes nothing in a parallel
    # projection but its depth; 1e-3 of the model stays below the sheet
    # thickness, so the die is still hidden by the sheet.
    tool = Transform(Input=tool)
    tool.Transform.Translate = [-1e-3 * size * c for c in look]
    tool_display = Show(tool, view)
    tool_display.ColorArrayName = ["POINTS", ""]
    shade = 0.45 + 0.12 * k
    tool_display.AmbientColor = tool_display.DiffuseColor = [shade] * 3
    tool_display.Opacity = 0.2
    # The faint surfaces alone hardly read as tools: outline their edges.
    edges = FeatureEdges(Input=ExtractSurface(Input=tool), BoundaryEdges=1,
                         FeatureEdges=0, NonManifoldEdges=0, ManifoldEdges=0)
    edges_display = Show(edges, view)
    edges_display.ColorArrayName = ["POINTS", ""]
    edges_display.AmbientColor = edges_display.DiffuseColor = [0.3] * 3
    edges_display.LineWidth = max(1.0, 2 * zoom)

label = Text(Text="punch travel %g mm" % time)
label_display = Show(label, view)
label_display.Color = [0, 0, 0]
label_display.FontSize = max(8, round(22 * zoom))
label_display.WindowLocation = "Upper Left Corner"

# Isometric: parallel projection, looking down the (-1, 1, -1) diagonal so
# the inside of the cup (punch moving along -z) faces the camera. Framed on
# the sheet alone (the bounding-sphere fit of ResetCamera leaves a flat
# sheet small), leaving the right-hand side to the colour bar.
centre = [0.5 * (bounds[2 * d] + bounds[2 * d + 1]) for d in range(3)]
up = [-look[2] * c for c in look]
up[2] += 1
up = [c / sum(u * u for u in up) ** 0.5 for c in up]
right = [look[1] * up[2] - look[2] * up[1], look[2] * up[0] - look[0] * up[2],
         look[0] * up[1] - look[1] * up[0]]
corners = [[bounds[i], bounds[2 + j], bounds[4 + k]]
           for i in (0, 1) for j in (0, 1) for k in (0, 1)]


def extent(axis):
    return max(abs(sum((p[d] - centre[d]) * axis[d] for d in range(3)))
               for p in corners)


view.CameraParallelProjection = 1
scale = 1.12 * max(extent(up), extent(right) / (0.82 * 1.6))
# Centred on 41 % of the width: the colour bar has the right-hand side.
focus = [centre[d] + 0.09 * 1.6 * scale * right[d] for d in range(3)]
view.CameraFocalPoint = focus
view.CameraPosition = [focus[d] - 10 * size * look[d] for d in range(3)]
view.CameraViewUp = up
view.CameraParallelScale = scale

SaveScreenshot(png_file, view, ImageResolution=[width, width * 5 // 8],
               TransparentBackground=0)
print("render: wrote %s" % png_file)
