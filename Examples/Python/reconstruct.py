#!/usr/bin/env python3
"""Rebuild a shape from its medial balls and measure how close it is.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/reconstruct.py \\
      [MESH.ply] [OUT.stl]
Without a mesh it uses the built-in demo shape. Prints the largest distance from the
reconstruction's vertices to the original surface, relative to its bounding-box diagonal.
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference
from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOPLY import vtkPLYReader

if len(sys.argv) > 1 and sys.argv[1].lower().endswith(".ply"):
    source = vtkPLYReader()
    source.SetFileName(sys.argv[1])
else:
    source = medialaxis.vtkMedialShapeSource()
surface = vtkTriangleFilter()
surface.SetInputConnection(source.GetOutputPort())
surface.Update()

sampler = medialaxis.vtkMedialAxisSampler()
sampler.SetInputConnection(surface.GetOutputPort())
sampler.SetNumberOfSamples(20000)
sampler.SetMinimumSeparationAngle(0)  # exact polyhedral balls: no protrusion
union = medialaxis.vtkMedialBallUnion()
union.SetInputConnection(sampler.GetOutputPort())
union.SetSampleDimensions(128, 128, 128)
union.Update()
rebuilt = union.GetOutput()

locator = vtkStaticCellLocator()
locator.SetDataSet(surface.GetOutput())
locator.BuildLocator()
closest, cell, sub, dist2 = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
distances = []
for p in vtk_to_numpy(rebuilt.GetPoints().GetData()):
    locator.FindClosestPoint(p, closest, cell, sub, dist2)
    distances.append(dist2.get() ** 0.5)
diagonal = surface.GetOutput().GetLength()
print(f"{rebuilt.GetNumberOfCells()} triangles; reconstruction to original: "
      f"max {100 * max(distances) / diagonal:.3f}%, mean {100 * np.mean(distances) / diagonal:.4f}% "
      "of the diagonal")

if len(sys.argv) > 2:
    writer = vtkSTLWriter()
    writer.SetInputData(rebuilt)
    writer.SetFileName(sys.argv[2])
    writer.Write()
