#!/usr/bin/env python3
"""The 2D medial graph of planar polygons: junctions, end points and arcs.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/junction_graph.py \\
      [POLYGONS.vtp|.vtk|.ply|.stl|.obj|.off] [OUT.vtp|.vtk|.ply|.ma|.csv]
Without an input it uses a square with a square hole. Prints every junction with its
radius and governor count, and the arc counts; OUT is written in the format its
extension names.
"""
import sys

import numpy as np

import medialaxis
from example_io import BALLS, check_output, open_input, write
from vtkmodules.util.numpy_support import vtk_to_numpy

out = sys.argv[2] if len(sys.argv) > 2 else None
check_output(out, BALLS)
frame = medialaxis.vtkMedialShapeSource()
frame.SetShapeToSquareFrame()  # the square [-2, 2]^2 with the hole [-1, 1]^2
source = open_input(sys.argv[1] if len(sys.argv) > 1 else None, frame)
junctions = medialaxis.vtkMedialJunctionFilter()
junctions.SetInputConnection(source.GetOutputPort())
junctions.Update()
if junctions.GetErrorCode() or junctions.GetOutput().GetNumberOfPoints() == 0:
    sys.exit(1)  # the filter said why
graph = junctions.GetOutput()

points = vtk_to_numpy(graph.GetPoints().GetData())
kind = vtk_to_numpy(graph.GetPointData().GetArray("MedialPointType"))
radius = vtk_to_numpy(graph.GetPointData().GetArray("Radius"))
governors = vtk_to_numpy(graph.GetPointData().GetArray("GovernorCount"))
arc_type = vtk_to_numpy(graph.GetCellData().GetArray("ArcType"))
for i in np.flatnonzero(kind == 2):
    x, y, _ = points[i]
    print(f"junction ({x:+.6f}, {y:+.6f})  radius {radius[i]:.6f}  governors {governors[i]}")
print(f"{(kind == 0).sum()} end points, {(arc_type == 0).sum()} linear and "
      f"{(arc_type == 1).sum()} parabolic arcs")

if out:
    write(graph, out, BALLS)
