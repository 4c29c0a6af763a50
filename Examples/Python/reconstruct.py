#!/usr/bin/env python3
"""Rebuild a shape from its medial balls and measure how close it is.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/reconstruct.py \\
      [MESH.ply|.obj|.stl|.off|.vtp|.vtk] [OUT.vtp|.vtk|.stl|.ply|.obj]
Without a mesh it uses the built-in demo shape; OUT is written in the format its
extension names. Prints the distance between the
reconstruction and the original in both directions (from the vertices, and from points
spread over the surfaces by area), relative to the original's bounding-box diagonal.
"""
import sys

import numpy as np

import medialaxis
from example_io import SURFACE, check_output, open_input, write
from vtkmodules.util.numpy_support import vtk_to_numpy

out = sys.argv[2] if len(sys.argv) > 2 else None
check_output(out, SURFACE)
source = open_input(sys.argv[1] if len(sys.argv) > 1 else None, medialaxis.vtkMedialShapeSource())

sampler = medialaxis.vtkMedialAxisSampler()
sampler.SetInputConnection(source.GetOutputPort())
sampler.SetNumberOfSamples(20000)
sampler.SetMinimumSeparationAngle(0)  # exact polyhedral balls: no protrusion
union = medialaxis.vtkMedialBallUnion()
union.SetInputConnection(sampler.GetOutputPort())
union.SetSampleDimensions(128, 128, 128)

error = medialaxis.vtkMedialReconstructionError()
error.SetOriginalConnection(source.GetOutputPort())
error.SetReconstructionConnection(union.GetOutputPort())
error.Update()
E = medialaxis.vtkMedialReconstructionError
to_original, to_rebuilt = E.RECONSTRUCTION_TO_ORIGINAL, E.ORIGINAL_TO_RECONSTRUCTION
rebuilt = error.GetOutput(0)  # the reconstruction, with each vertex's SurfaceDistance
distance = vtk_to_numpy(rebuilt.GetPointData().GetArray("SurfaceDistance"))
print(f"{rebuilt.GetNumberOfCells()} triangles; reconstruction to original: "
      f"max {100 * error.GetVertexMaxError()[to_original]:.3f}%, "
      f"mean {100 * error.GetVertexMeanError()[to_original]:.4f}% of the diagonal "
      f"(by area: max {100 * error.GetAreaMaxError()[to_original]:.3f}%); "
      f"{np.count_nonzero(distance > 0.001 * error.GetDiagonal())} vertices farther than 0.1%")
print(f"original to reconstruction: max {100 * error.GetVertexMaxError()[to_rebuilt]:.3f}%, "
      f"mean {100 * error.GetVertexMeanError()[to_rebuilt]:.4f}% "
      f"(by area: max {100 * error.GetAreaMaxError()[to_rebuilt]:.3f}%)")

if out:
    write(rebuilt, out, SURFACE)
