#!/usr/bin/env python3
"""Medial axis of a mesh to a PNG, offscreen.

Usage (from the build tree; needs an X display, e.g. under xvfb-run):
  PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
      Examples/Python/medial_axis_png.py [MESH.ply|.stl|.obj|.off|.vtp|.vtk] OUT.png
Without a mesh it uses the built-in demo shape. The picture is vtkMedialScene's with
its defaults (framing, view, size, colour map and colour bar), sampled as
`medial-axis` samples by default: the same picture as `medial-axis MESH --render OUT.png`.
"""
import sys

import medialaxis
from example_io import open_input


def render(surface, medial, out_png=None, size=None):
    """Renders the translucent surface and the medial points coloured by radius; writes
    out_png when given. Returns the render window."""
    scene = medialaxis.vtkMedialScene()
    scene.SetSurface(surface)
    scene.SetMedial(medial)
    if size:
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
    if not argv[-1].lower().endswith(".png"):
        print(f"{argv[0]}: error: the picture needs a .png name, got '{argv[-1]}'", file=sys.stderr)
        return 1
    source = open_input(argv[1] if len(argv) == 3 else None, medialaxis.vtkMedialShapeSource())
    sampler = medialaxis.vtkMedialAxisSampler()  # medial-axis's defaults: 10000 samples, seed 1
    sampler.SetInputConnection(source.GetOutputPort())
    sampler.Update()
    render(source.GetOutputDataObject(0), sampler.GetOutput(), argv[-1])
    print(f"{sampler.GetOutput().GetNumberOfPoints()} medial points -> {argv[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
