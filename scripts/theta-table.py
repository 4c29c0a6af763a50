#!/usr/bin/env python3
"""Measures how MinimumSeparationAngle (theta) recovers a smooth sphere's medial axis.

For geodesic spheres of several resolutions and several theta, prints radius/R
(minimum, median) and the largest centre offset |c|/R over the samples. The exact
answer for the smooth sphere is r = R, c = 0. Run from the build tree:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 scripts/theta-table.py
"""
import statistics
import sys

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy

SAMPLES = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
LEVELS = [3, 4, 5, 6, 7]
THETAS = [0, 10, 20, 30, 45, 60, 75]

print("| triangles | theta | min r/R | median r/R | max abs(c)/R |")
print("|---|---|---|---|---|")
for level in LEVELS:
    sphere = medialaxis.vtkMedialShapeSource()
    sphere.SetShapeToSphere()
    sphere.SetResolution(level)
    sphere.Update()
    for theta in THETAS:
        sampler = medialaxis.vtkMedialAxisSampler()
        sampler.SetInputConnection(sphere.GetOutputPort())
        sampler.SetNumberOfSamples(SAMPLES)
        sampler.SetMinimumSeparationAngle(theta)
        sampler.SetMethodToShrinkingBall()
        sampler.SetMaximumProtrusion(1.0)  # the angle rule alone: balls are not shrunk
        sampler.Update()
        out = sampler.GetOutput()
        radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
        centres = vtk_to_numpy(out.GetPoints().GetData())
        offset = (centres ** 2).sum(axis=1) ** 0.5
        print(f"| {sphere.GetOutput().GetNumberOfCells()} | {theta} | {radius.min():.4f} | "
              f"{statistics.median(radius):.4f} | {offset.max():.4f} |", flush=True)
