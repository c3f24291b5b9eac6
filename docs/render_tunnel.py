"""The standard figure of a tunnel from an adit output folder, with ParaView's Python.

    xvfb-run pvpython docs/render_tunnel.py out/tunnel [figure.png] [--step N] [--half-width W]
        [--width PIXELS]

Draws the last output step (or step N), ready for a report: a title (the scene, the stage and
its cycle), axes in metres and a scale bar; the most compressive principal stress sigma1 from
the recovered nodal field (`sigma1_nodal`) as colour, with its colour bar in MPa and its
contour lines (the zones' sigma1 from its 1st to its 99th percentile); the yielded zones
(`state` not 0) hatched over it; the joints coloured by state (grey elastic, red slipping, blue
open); and the bolts and liners coloured by their axial force (kN/m, tension positive) on a
colour bar of their own. The view is centred on the supports when the step has any (else on the
model) and spans W metres either side (default: 1.2 times the supports' extent, else the whole
model). Without a figure name it writes `<folder>/figure.png`. It reads the `.pvd` collection
only to find each step's files.
"""

import argparse
import os
import xml.etree.ElementTree as ET

import numpy as np
from paraview import servermanager
from vtk.util.numpy_support import vtk_to_numpy

from paraview.simple import (
    Calculator,
    ColorBy,
    Contour,
    CreateView,
    GetColorTransferFunction,
    GetScalarBar,
    Line,
    Render,
    SaveScreenshot,
    Show,
    Text,
    Threshold,
    XMLUnstructuredGridReader,
)


def step_files(folder, step):
    """The files of output step `step` (-1: the last) by kind: zones, contacts, joints, supports."""
    pvds = [f for f in os.listdir(folder) if f.endswith(".pvd") and not f.endswith("_mesh.pvd")]
    if len(pvds) != 1:
        raise SystemExit(f"{folder}: expected one .pvd collection, found {pvds}")
    root = ET.parse(os.path.join(folder, pvds[0])).getroot()
    steps = {}
    for d in root.iter("DataSet"):
        steps.setdefault(float(d.get("timestep")), []).append(d)
    times = sorted(steps)
    if not times:
        raise SystemExit(f"{pvds[0]} lists no output step")
    sets = steps[times[step]]
    files = {}
    for d in sets:
        name = d.get("file")
        kind = d.get("name") or name.rsplit("_", 2)[-2]
        files[kind] = os.path.join(folder, name)
    scene = pvds[0][: -len(".pvd")]
    return files, sets[0].get("stage", ""), scene, times[step]


def nice_length(span):
    """A round length (1, 2 or 5 times a power of ten) near a fifth of `span`, m."""
    target = span / 5.0
    power = 10.0 ** np.floor(np.log10(target))
    return max(k * power for k in (1.0, 2.0, 5.0) if k * power <= target)


def black_text(text, view, location, size=18):
    """`text` drawn in black at `location` of the view ('Upper Center', 'Lower Left', ...)."""
    label = Text(Text=text)
    shown = Show(label, view)
    shown.WindowLocation = location
    shown.FontSize = size
    shown.Color = [0.0, 0.0, 0.0]
    return shown


def scale_bar(view, centre, half):
    """A bar of a round length at the bottom of the view, with its length in metres."""
    length = nice_length(2 * half)
    x0, y0 = centre[0] - 0.5 * length, centre[1] - 0.9 * half
    bar = Line(Point1=[x0, y0, 0.01], Point2=[x0 + length, y0, 0.01])
    shown = Show(bar, view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.DiffuseColor = [0.0, 0.0, 0.0]
    shown.AmbientColor = [0.0, 0.0, 0.0]
    shown.LineWidth = 5.0
    label = Text(Text=f"{length:g} m")
    shown = Show(label, view)
    shown.TextPropMode = "Billboard 3D Text"
    shown.BillboardPosition = [x0, y0 + 0.025 * half, 0.01]
    shown.FontSize = 16
    shown.Color = [0.0, 0.0, 0.0]


def metre_axes(view, centre, half, aspect):
    """Axes along the edges of the part of the model in view, their ticks in metres."""
    grid = view.AxesGrid
    grid.Visibility = 1
    grid.UseCustomBounds = 1
    w, h = 0.8 * half * aspect, 0.86 * half
    grid.CustomBounds = [centre[0] - w, centre[0] + w, centre[1] - h, centre[1] + h, 0.0, 0.0]
    grid.XTitle = "x (m)"
    grid.YTitle = "y (m)"
    grid.ShowGrid = 0
    for part in ("XTitle", "YTitle", "XLabel", "YLabel"):
        setattr(grid, part + "Color", [0.0, 0.0, 0.0])
    grid.GridColor = [0.0, 0.0, 0.0]


def placed_bar(lut, view, title, position):
    """The colour bar of `lut` titled `title` at `position` (fractions of the view)."""
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = position
    bar.ScalarBarLength = 0.28
    return bar


def show_by(source, view, kind, function, name, preset, symmetric):
    """The cells of `source` of `kind` (0 bolts, 1 liners) drawn as thick lines coloured by
    `function` of their cell data (`name`): a diverging map symmetric about zero when
    `symmetric`, else from the least to the most."""
    some = Threshold(Input=source)
    some.Scalars = ["CELLS", "kind"]
    try:
        some.LowerThreshold, some.UpperThreshold = kind - 0.5, kind + 0.5
    except AttributeError:  # ParaView before 5.10
        some.ThresholdRange = [kind - 0.5, kind + 0.5]
    values = Calculator(Input=some)
    values.AttributeType = "Cell Data"
    values.ResultArrayName = name
    values.Function = function
    drawn = Show(values, view)
    ColorBy(drawn, ("CELLS", name))
    lut = GetColorTransferFunction(name)
    lut.ApplyPreset(preset, True)
    data = vtk_to_numpy(servermanager.Fetch(values).GetCellData().GetArray(name))
    if symmetric:
        most = max(float(np.abs(data).max()), 1e-9)
        lut.RescaleTransferFunction(-most, most)
    else:
        lut.RescaleTransferFunction(float(data.min()), float(data.max()) + 1e-9)
    drawn.LineWidth = 4.0
    drawn.SetScalarBarVisibility(view, True)
    return lut


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("figure", nargs="?")
    parser.add_argument("--step", type=int, default=-1)
    parser.add_argument("--half-width", type=float)
    parser.add_argument("--width", type=int, default=1200, help="pixels (height: 5/6 of it)")
    args = parser.parse_args()
    files, stage, scene, cycle = step_files(args.folder, args.step)
    figure = args.figure or os.path.join(args.folder, "figure.png")

    view = CreateView("RenderView")
    pixels = [args.width, args.width * 5 // 6]
    view.ViewSize = pixels
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass

    zones = XMLUnstructuredGridReader(FileName=[files["zones"]])
    mpa = Calculator(Input=zones)
    mpa.ResultArrayName = "sigma1 (MPa)"
    mpa.Function = "sigma1_nodal/1e6"
    shown = Show(mpa, view)
    ColorBy(shown, ("POINTS", "sigma1 (MPa)"))
    lut = GetColorTransferFunction("sigma1 (MPa)")
    lut.ApplyPreset("Jet", True)
    lut.InvertTransferFunction()
    bar = GetScalarBar(lut, view)
    bar.Title = "sigma1, most compressive (MPa)"
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    shown.SetScalarBarVisibility(view, True)

    # Colours and contour levels span the zones' sigma1 from its 1st to 99th percentile, so that
    # a stress concentration at a model corner does not wash out the tunnel.
    grid = servermanager.Fetch(zones)
    sigma1 = vtk_to_numpy(grid.GetCellData().GetArray("sigma1")) / 1e6
    lo, hi = np.percentile(sigma1, [1.0, 99.0])
    lut.RescaleTransferFunction(lo, hi)
    lines = Contour(Input=mpa)
    lines.ContourBy = ["POINTS", "sigma1 (MPa)"]
    lines.Isosurfaces = [lo + (hi - lo) * k / 12.0 for k in range(1, 12)]
    drawn = Show(lines, view)
    drawn.ColorArrayName = ["POINTS", ""]
    drawn.DiffuseColor = [0.1, 0.1, 0.1]
    drawn.AmbientColor = [0.1, 0.1, 0.1]
    drawn.LineWidth = 1.0

    # The yielded zones hatched by their own edges over the stress.
    yielded = Threshold(Input=zones)
    yielded.Scalars = ["CELLS", "state"]
    try:
        yielded.LowerThreshold, yielded.UpperThreshold = 0.5, 1e9
    except AttributeError:  # ParaView before 5.10
        yielded.ThresholdRange = [0.5, 1e9]
    hatch = Show(yielded, view)
    hatch.Representation = "Wireframe"
    hatch.ColorArrayName = ["POINTS", ""]
    hatch.AmbientColor = [0.15, 0.15, 0.15]
    hatch.DiffuseColor = [0.15, 0.15, 0.15]
    hatch.Opacity = 0.35
    yielded_count = yielded.GetDataInformation().GetNumberOfCells()

    if "joints" in files:
        joints = XMLUnstructuredGridReader(FileName=[files["joints"]])
        traces = Show(joints, view)
        ColorBy(traces, ("CELLS", "state"))
        state = GetColorTransferFunction("state")
        state.InterpretValuesAsCategories = 1
        state.Annotations = ["0", "elastic", "1", "slipping", "2", "open"]
        state.IndexedColors = [0.55, 0.55, 0.55, 0.85, 0.1, 0.1, 0.1, 0.3, 0.9]
        traces.LineWidth = 2.0
        traces.SetScalarBarVisibility(view, True)
        legend = GetScalarBar(state, view)
        legend.Title = "joint state"
        legend.TitleColor = [0, 0, 0]
        legend.LabelColor = [0, 0, 0]

    centre, half = None, args.half_width
    if "supports" in files:
        supports = XMLUnstructuredGridReader(FileName=[files["supports"]])
        supports.UpdatePipeline()
        x0, x1, y0, y1, _, _ = supports.GetDataInformation().GetBounds()
        if x1 >= x0:
            grid = servermanager.Fetch(supports)
            kind = vtk_to_numpy(grid.GetCellData().GetArray("kind"))
            if (kind == 0).any():
                lut = show_by(supports, view, 0, "bolt_force_n/1e3", "bolt force (kN)",
                              "Cool to Warm", True)
                placed_bar(lut, view, "bolts: force per bolt (kN, tension +)", [0.02, 0.06])
            if (kind == 1).any():
                lut = show_by(supports, view, 1, "-axial_force/1e6", "liner thrust (MN/m)",
                              "Inferno (matplotlib)", False)
                placed_bar(lut, view, "liners: thrust (MN/m)", [0.02, 0.42])
            centre = [(x0 + x1) / 2, (y0 + y1) / 2]
            half = half or 1.2 * max(x1 - x0, y1 - y0)
    if centre is None:
        x0, x1, y0, y1, _, _ = zones.GetDataInformation().GetBounds()
        centre = [(x0 + x1) / 2, (y0 + y1) / 2]
        half = half or 0.5 * max(x1 - x0, y1 - y0)

    title = f"{scene}: stage '{stage}', cycle {cycle:g}" if stage else f"{scene}: cycle {cycle:g}"
    note = f"\nhatched: the {yielded_count} yielded zones" if yielded_count else ""
    black_text(title + note, view, "Upper Center", 18)
    metre_axes(view, centre, half, pixels[0] / pixels[1])
    scale_bar(view, centre, half)

    Render(view)  # the first render resets the camera: frame the view after it
    view.CameraPosition = [centre[0], centre[1], 10 * half]
    view.CameraFocalPoint = [centre[0], centre[1], 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half
    Render(view)
    SaveScreenshot(figure, view, ImageResolution=pixels)
    print(f"{figure}: {title}, sigma1 from {lo:.1f} to {hi:.1f} MPa, {yielded_count} yielded zones")


if __name__ == "__main__":
    main()
