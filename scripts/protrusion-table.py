#!/usr/bin/env python3
"""Measures how far medial balls cross the input surface, for several theta, with
the angle rule alone (MaximumProtrusion 1: balls are not shrunk to be inscribed).

With theta > 0, surface inside the cap around the sample point is ignored, so a
ball can grow through the surface there. (The default MaximumProtrusion then
shrinks such balls; build/bin/medial-solids-bench measures that.) Protrusion = Radius
minus the distance from the centre to the surface (vtkMedialBallProtrusion), relative
to the bounding-box diagonal. Run from the source tree after a build:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 scripts/protrusion-table.py \\
      ../shared/data/meshes/horse.ply [SAMPLES]
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkTriangleFilter

path = sys.argv[1]
samples = int(sys.argv[2]) if len(sys.argv) > 2 else 5000
reader = medialaxis.vtkMedialFileReader()
reader.SetFileName(path)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(reader.GetOutputPort())
triangles.Update()
surface = triangles.GetOutput()
diagonal = surface.GetLength()

print("| theta | max protrusion | 99th percentile | mean | median r |")
print("|---|---|---|---|---|")
for theta in (0, 30, 45, 60):
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputData(surface)
    sampler.SetNumberOfSamples(samples)
    sampler.SetMinimumSeparationAngle(theta)
    sampler.SetMaximumProtrusion(1.0)
    measure = medialaxis.vtkMedialBallProtrusion()
    measure.SetSurfaceData(surface)
    measure.SetBallsConnection(sampler.GetOutputPort())
    measure.Update()
    balls = measure.GetOutput()
    radius = vtk_to_numpy(balls.GetPointData().GetArray("Radius"))
    protrusion = vtk_to_numpy(balls.GetPointData().GetArray("Protrusion")) / diagonal
    print(f"| {theta} | {100 * measure.GetMaxProtrusion():.3f}% | {100 * np.percentile(protrusion, 99):.3f}% | "
          f"{100 * protrusion.mean():.4f}% | {np.median(radius) / diagonal:.4f} |", flush=True)
