#!/usr/bin/env python3
"""The medial mesh of a closed surface: topology, a .ma file and a picture.

Usage (from the build tree; the picture needs an X display, e.g. under xvfb-run):
  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
      Examples/Python/medial_mesh.py [MESH.ply|.obj|.stl|.off|.vtp|.vtk] [OUT.ma|.vtp|.vtk|.ply|.csv] [OUT.png] [--by-type]
Without a mesh it uses the built-in demo shape. Prints the mesh's size and topology next
to the solid's. The picture (vtkMedialScene) shows the mesh inside the translucent
surface, coloured by ball radius (or, with --by-type, by MedialPointType), seen along
the surface's shortest bounding-box side with the middle one up.
"""
import sys

import medialaxis
from example_io import BALLS, check_output, open_input, write


def render(surface, mesh, out_png, by_type=False):
    scene = medialaxis.vtkMedialScene()
    scene.SetSurface(surface)
    scene.SetMedial(mesh)
    scene.SetSurfaceOpacity(0.18)
    scene.SetWindowSize(1000, 760)
    if by_type:
        scene.SetColorByToPointType()
    b = surface.GetBounds()
    sides = sorted(range(3), key=lambda k: b[2 * k + 1] - b[2 * k])
    centre = [(b[2 * k] + b[2 * k + 1]) / 2 for k in range(3)]
    # Look along the shortest side, a little from the front and above.
    position = [centre[k] + (1.0 if k == sides[0] else 0.0) for k in range(3)]
    position[sides[2]] += 0.45
    position[sides[1]] += 0.25
    scene.SetView(position, centre, [1.0 if k == sides[1] else 0.0 for k in range(3)])
    scene.SetZoom(1.2)
    if not scene.WritePNG(out_png):
        raise RuntimeError(f"cannot write {out_png}")


def main(argv):
    args = [a for a in argv[1:] if a != "--by-type"]
    png_path = next((a for a in args if a.endswith(".png")), None)
    args = [a for a in args if a != png_path]
    # The first name is the input when a second one (the mesh) follows it, or when it
    # is a surface format that cannot hold balls.
    ball_formats = medialaxis.vtkMedialFileWriter.GetExtensions(BALLS).split()
    mesh_path = None
    if len(args) > 1 or (args and not args[0].lower().endswith(tuple(ball_formats))):
        mesh_path = args.pop(0)
    out_path = args[0] if args else None
    check_output(out_path, BALLS)
    source = open_input(mesh_path, medialaxis.vtkMedialShapeSource())
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
    if out_path:
        write(mesh, out_path, BALLS)
    if png_path:
        render(source.GetOutputDataObject(0), mesh, png_path, "--by-type" in argv)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
