#!/usr/bin/python3
"""Renders a planar slice of a blayer .vtu to a PNG, headless.

The slice cuts every cell it crosses, so the picture shows the layer structure the way a
user inspects it in ParaView (Slice filter, surface with edges). Run it under a virtual X
server:  xvfb-run -a /usr/bin/python3 scripts/render_slice.py MESH.vtu OUT.png ...
(packages python3-vtk9, xvfb, xauth: scripts/install-deps.sh --extras).
"""
import argparse

import vtk


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("mesh")
    ap.add_argument("png")
    ap.add_argument("--origin", type=float, nargs=3, required=True, help="a point of the slice plane")
    ap.add_argument("--normal", type=float, nargs=3, required=True, help="the slice plane's normal")
    ap.add_argument("--focus", type=float, nargs=3, help="point at the centre of the picture (default: origin)")
    ap.add_argument("--width", type=float, required=True, help="width of the region shown, in model units")
    ap.add_argument("--up", type=float, nargs=3, default=(0, 0, 1), help="view-up direction")
    ap.add_argument("--array", default="layer", help="cell array to colour by")
    ap.add_argument("--title", default="")
    ap.add_argument("--size", type=int, nargs=2, default=(900, 600))
    a = ap.parse_args()

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(a.mesh)
    reader.Update()
    grid = reader.GetOutput()

    plane = vtk.vtkPlane()
    plane.SetOrigin(*a.origin)
    plane.SetNormal(*a.normal)
    cutter = vtk.vtkCutter()
    cutter.SetCutFunction(plane)
    cutter.SetInputData(grid)
    cutter.Update()
    cut = cutter.GetOutput()

    arr = cut.GetCellData().GetArray(a.array)
    if arr is None:
        raise SystemExit("error: %s has no cell array '%s'" % (a.mesh, a.array))
    lo, hi = arr.GetRange()
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(lo, hi)
    lut.Build()

    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputData(cut)
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray(a.array)
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(lo, hi)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.1, 0.1, 0.1)
    actor.GetProperty().SetLineWidth(1.0)
    actor.GetProperty().LightingOff()

    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(a.array)
    bar.SetNumberOfLabels(5)
    bar.SetWidth(0.08)
    bar.SetHeight(0.6)
    bar.SetPosition(0.9, 0.2)

    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.AddActor(actor)
    ren.AddActor2D(bar)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    if a.title:
        text = vtk.vtkTextActor()
        text.SetInput(a.title)
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(18)
        text.SetPosition(10, a.size[1] - 30)
        ren.AddActor2D(text)

    focus = a.focus or a.origin
    n = a.normal
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(*focus)
    cam.SetPosition(focus[0] + n[0], focus[1] + n[1], focus[2] + n[2])
    cam.SetViewUp(*a.up)
    cam.ParallelProjectionOn()
    cam.SetParallelScale(a.width * a.size[1] / a.size[0] / 2)
    ren.ResetCameraClippingRange()

    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(*a.size)
    win.Render()
    shot = vtk.vtkWindowToImageFilter()
    shot.SetInput(win)
    shot.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(a.png)
    writer.SetInputConnection(shot.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main()
