"""The standard figure of a tunnel from an adit output folder, with ParaView's Python.

    xvfb-run pvpython docs/render_tunnel.py out/tunnel [figure.png] [--step N] [--half-width W]
        [--width PIXELS]

Draws the last output step (or step N): the most compressive principal stress sigma1 from the
recovered nodal field (`sigma1_nodal`, MPa) as colour with its contour lines (the zones' sigma1
from its 1st to its 99th percentile), the joints coloured by
state (grey elastic, red slipping, blue open) and the supports (black). The view is centred on the
supports when the model has any (else on the model) and spans W metres either side (default: 1.2
times the supports' extent, else the whole model). Without a figure name it writes
`<folder>/figure.png`. It reads the `.pvd` collection only to find each step's files.
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
    Render,
    SaveScreenshot,
    Show,
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
    return files, sets[0].get("stage", "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("figure", nargs="?")
    parser.add_argument("--step", type=int, default=-1)
    parser.add_argument("--half-width", type=float)
    parser.add_argument("--width", type=int, default=1200, help="pixels (height: 5/6 of it)")
    args = parser.parse_args()
    files, stage = step_files(args.folder, args.step)
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
    bar.Title = "sigma1 (MPa)"
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
            drawn = Show(supports, view)
            drawn.ColorArrayName = ["POINTS", ""]
            drawn.DiffuseColor = [0.0, 0.0, 0.0]
            drawn.AmbientColor = [0.0, 0.0, 0.0]
            drawn.LineWidth = 3.0
            centre = [(x0 + x1) / 2, (y0 + y1) / 2]
            half = half or 1.2 * max(x1 - x0, y1 - y0)
    if centre is None:
        x0, x1, y0, y1, _, _ = zones.GetDataInformation().GetBounds()
        centre = [(x0 + x1) / 2, (y0 + y1) / 2]
        half = half or 0.5 * max(x1 - x0, y1 - y0)

    Render(view)  # the first render resets the camera: frame the view after it
    view.CameraPosition = [centre[0], centre[1], 10 * half]
    view.CameraFocalPoint = [centre[0], centre[1], 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half
    Render(view)
    SaveScreenshot(figure, view, ImageResolution=pixels)
    print(f"{figure}: step '{stage}', sigma1 from {lo:.1f} to {hi:.1f} MPa")


if __name__ == "__main__":
    main()
