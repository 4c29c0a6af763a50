#!/usr/bin/env python3
"""Measures how far medial balls cross the input surface, for several theta, with
the angle rule alone (MaximumProtrusion 1: balls are not shrunk to be inscribed).

With theta > 0, surface inside the cap around the sample point is ignored, so a
ball can grow through the surface there. (The default MaximumProtrusion then
shrinks such balls; build/bin/medial-solids-bench measures that.) Protrusion = Radius minus the distance
from the centre to the surface (VTK's cell locator), relative to the bounding-box
diagonal. Run from the source tree after a build:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 scripts/protrusion-table.py \\
      ../shared/data/meshes/horse.ply [SAMPLES]
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference
from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader

path = sys.argv[1]
samples = int(sys.argv[2]) if len(sys.argv) > 2 else 5000
reader = vtkPLYReader() if path.lower().endswith(".ply") else vtkOBJReader()
reader.SetFileName(path)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(reader.GetOutputPort())
triangles.Update()
surface = triangles.GetOutput()
diagonal = surface.GetLength()
locator = vtkStaticCellLocator()
locator.SetDataSet(surface)
locator.BuildLocator()

print("| theta | max protrusion | 99th percentile | mean | median r |")
print("|---|---|---|---|---|")
for theta in (0, 30, 45, 60):
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputData(surface)
    sampler.SetNumberOfSamples(samples)
    sampler.SetMinimumSeparationAngle(theta)
    sampler.SetMaximumProtrusion(1.0)
    sampler.Update()
    out = sampler.GetOutput()
    radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
    centres = vtk_to_numpy(out.GetPoints().GetData())
    closest, cell, sub, dist2 = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
    protrusion = np.empty(len(radius))
    for i, c in enumerate(centres):
        locator.FindClosestPoint(c, closest, cell, sub, dist2)
        protrusion[i] = (radius[i] - dist2.get() ** 0.5) / diagonal
    print(f"| {theta} | {100 * protrusion.max():.3f}% | {100 * np.percentile(protrusion, 99):.3f}% | "
          f"{100 * protrusion.mean():.4f}% | {np.median(radius) / diagonal:.4f} |", flush=True)
