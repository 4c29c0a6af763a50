#!/usr/bin/env python3
"""The medial mesh of a closed surface: topology, a .ma file and a picture.

Usage (from the build tree; the picture needs an X display, e.g. under xvfb-run):
  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
      Examples/Python/medial_mesh.py [MESH.ply|.obj|.stl|.vtp] [OUT.ma] [OUT.png]
Without a mesh it uses the built-in demo shape. Prints the mesh's size and topology next
to the solid's. The picture shows the mesh coloured by ball radius inside the
translucent surface, seen along the surface's shortest bounding-box axis.
"""
import sys

import medialaxis
from vtkmodules.vtkCommonCore import vtkLookupTable
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


def render(surface, mesh, out_png, size=(1000, 760)):
    surface_mapper = vtkPolyDataMapper()
    surface_mapper.SetInputData(surface)
    surface_mapper.ScalarVisibilityOff()
    shell = vtkActor()
    shell.SetMapper(surface_mapper)
    shell.GetProperty().SetColor(0.80, 0.82, 0.86)
    shell.GetProperty().SetOpacity(0.18)
    colours = vtkLookupTable()
    colours.SetHueRange(0.667, 0.0)  # blue (thin) to red (thick)
    colours.Build()
    mesh_mapper = vtkPolyDataMapper()
    mesh_mapper.SetInputData(mesh)
    mesh_mapper.SetLookupTable(colours)
    mesh_mapper.SetScalarModeToUsePointFieldData()
    mesh_mapper.SelectColorArray("Radius")
    mesh_mapper.SetScalarRange(mesh.GetPointData().GetArray("Radius").GetRange())
    medial = vtkActor()
    medial.SetMapper(mesh_mapper)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(shell)
    renderer.AddActor(medial)
    # Look along the shortest side of the box, with the middle one up.
    b = surface.GetBounds()
    sides = sorted(range(3), key=lambda k: b[2 * k + 1] - b[2 * k])
    camera = renderer.GetActiveCamera()
    centre = [(b[2 * k] + b[2 * k + 1]) / 2 for k in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([centre[k] + (1.0 if k == sides[0] else 0.0) for k in range(3)])
    camera.SetViewUp([1.0 if k == sides[1] else 0.0 for k in range(3)])
    renderer.ResetCamera()
    camera.Azimuth(25)
    camera.Elevation(15)
    renderer.ResetCamera()
    camera.Zoom(1.35)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(out_png)
    writer.Write()


def main(argv):
    paths = argv[1:]
    mesh_path = paths.pop(0) if paths and not paths[0].endswith((".ma", ".png")) else None
    ma_path = next((p for p in paths if p.endswith(".ma")), None)
    png_path = next((p for p in paths if p.endswith(".png")), None)
    source = surface_source(mesh_path)
    source.Update()
    medial_mesh = medialaxis.vtkMedialMeshFilter()
    medial_mesh.SetInputConnection(source.GetOutputPort())
    medial_mesh.Update()
    mesh = medial_mesh.GetOutput()
    solid = (f"the solid's {medial_mesh.GetSolidEulerCharacteristic()} and {medial_mesh.GetSolidComponents()}"
             if medial_mesh.GetHasSolidTopology() else "no solid (open surface)")
    print(f"medial mesh: {mesh.GetNumberOfPoints()} vertices, {medial_mesh.GetNumberOfEdges()} edges, "
          f"{mesh.GetNumberOfPolys()} triangles; Euler characteristic {medial_mesh.GetEulerCharacteristic()}, "
          f"{medial_mesh.GetNumberOfComponents()} component(s); {solid}")
    if ma_path:
        writer = medialaxis.vtkMedialMeshWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(ma_path)
        writer.Write()
    if png_path:
        render(source.GetOutput(), mesh, png_path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
