#!/usr/bin/env python3
"""Medial axis of a mesh to a PNG, offscreen.

Usage (from the build tree; needs an X display, e.g. under xvfb-run):
  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
      Examples/Python/medial_axis_png.py [MESH.ply|.stl|.obj|.off|.vtp|.vtk] OUT.png
Without a mesh it uses the built-in demo shape. The picture is vtkMedialScene's, the
same as `medial-axis --render`.
"""
import sys

import medialaxis


def surface_source(path):
    if path is None:
        return medialaxis.vtkMedialShapeSource()
    reader = medialaxis.vtkMedialFileReader()  # the reader for the file's extension
    reader.SetFileName(path)
    return reader


def render(surface, medial, out_png=None, size=(800, 600)):
    """Renders the translucent surface and the medial points coloured by radius; writes
    out_png when given. Returns the render window."""
    scene = medialaxis.vtkMedialScene()
    scene.SetSurface(surface)
    scene.SetMedial(medial)
    scene.SetWindowSize(*size)
    if out_png:
        if not scene.WritePNG(out_png):
            raise RuntimeError(f"cannot write {out_png}")
    else:
        scene.Render()
    return scene.GetRenderWindow()


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
    render(source.GetOutputDataObject(0), sampler.GetOutput(), argv[-1])
    print(f"{sampler.GetOutput().GetNumberOfPoints()} medial points -> {argv[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
