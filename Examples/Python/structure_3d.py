#!/usr/bin/env python3
"""3D medial structure of a box: governor counts and point types of the sampled balls,
and the exact seam points and junction vertices between them.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/structure_3d.py \\
      [MESH.vtp|.vtk|.ply|.stl|.obj|.off] [OUT.vtp|.vtk|.ply|.ma|.csv]
Without a mesh it uses a 3 x 2 x 1 box. Prints the balls per MedialPointType, then
every junction vertex with its radius and governor count. OUT gets the exact seam
points and junction vertices, in the format its extension names.
"""
import sys

import numpy as np

import medialaxis
from example_io import BALLS, check_output, open_input, write
from vtkmodules.util.numpy_support import vtk_to_numpy

out = sys.argv[2] if len(sys.argv) > 2 else None
check_output(out, BALLS)
box = medialaxis.vtkMedialShapeSource()
box.SetShapeToBox()  # 3 x 2 x 1, centred at the origin
box = open_input(sys.argv[1] if len(sys.argv) > 1 else None, box)
sampler = medialaxis.vtkMedialAxisSampler()
sampler.SetInputConnection(box.GetOutputPort())
sampler.SetNumberOfSamples(3000)
sampler.SetMinimumSeparationAngle(0)  # the exact medial axis of the polyhedron
classifier = medialaxis.vtkMedialBallClassifier()
classifier.SetInputConnection(sampler.GetOutputPort())
classifier.SetSurfaceConnection(box.GetOutputPort())
classifier.SetMinimumSeparationAngle(0)
classifier.Update()

kind = vtk_to_numpy(classifier.GetOutput().GetPointData().GetArray("MedialPointType"))
names = ["rim", "sheet", "seam", "junction"]
print("balls: " + ", ".join(f"{(kind == t).sum()} {names[t]}" for t in range(4)))

exact = classifier.GetOutput(1)
points = vtk_to_numpy(exact.GetPoints().GetData())
exact_kind = vtk_to_numpy(exact.GetPointData().GetArray("MedialPointType"))
radius = vtk_to_numpy(exact.GetPointData().GetArray("Radius"))
governors = vtk_to_numpy(exact.GetPointData().GetArray("GovernorCount"))
print(f"{(exact_kind == 2).sum()} exact seam points, {(exact_kind == 3).sum()} junction vertices")
order = np.lexsort((points[:, 2], points[:, 1], points[:, 0]))
for i in order[exact_kind[order] == 3]:
    x, y, z = points[i] + 0.0  # no negative zeros
    print(f"junction ({x:+.6f}, {y:+.6f}, {z:+.6f})  radius {radius[i]:.6f}  governors {governors[i]}")

if out:
    write(exact, out, BALLS)
