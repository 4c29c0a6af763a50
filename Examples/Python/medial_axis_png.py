#!/usr/bin/env python3
"""Medial axis of a mesh to a PNG, offscreen.

Usage (from the build tree; needs an X display, e.g. under xvfb-run):
  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
      Examples/Python/medial_axis_png.py [MESH.ply|.stl|.obj|.vtp] OUT.png
Without a mesh it uses the built-in demo shape.
"""
import sys

import medialaxis
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL backend)

READERS = {".ply": vtkPLYReader, ".stl": vtkSTLReader, ".obj": vtkOBJReader, ".vtp": vtkXMLPolyDataReader}


def surface_source(path):
    if path is None:
        return medialaxis.vtkMedialShapeSource()
    reader = READERS[path[path.rfind("."):].lower()]()
    reader.SetFileName(path)
    return reader


def render(surface_port, medial, out_png, size=(800, 600)):
    surface_mapper = vtkPolyDataMapper()
    surface_mapper.SetInputConnection(surface_port)
    surface_mapper.ScalarVisibilityOff()
    surface = vtkActor()
    surface.SetMapper(surface_mapper)
    surface.GetProperty().SetOpacity(0.2)
    medial_mapper = vtkPolyDataMapper()
    medial_mapper.SetInputData(medial)
    medial_mapper.SetScalarRange(medial.GetPointData().GetArray("Radius").GetRange())
    points = vtkActor()
    points.SetMapper(medial_mapper)
    points.GetProperty().SetPointSize(4)
    points.GetProperty().RenderPointsAsSpheresOn()
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(surface)
    renderer.AddActor(points)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.5)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    if out_png:
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(out_png)
        writer.Write()
    return window


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 1
    mesh = argv[1] if len(argv) == 3 else None
    source = surface_source(mesh)
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputConnection(source.GetOutputPort())
    sampler.SetNumberOfSamples(20000)
    sampler.Update()
    render(source.GetOutputPort(), sampler.GetOutput(), argv[-1])
    print(f"{sampler.GetOutput().GetNumberOfPoints()} medial points -> {argv[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
