#!/usr/bin/env python3
"""The 2D medial graph of a polygon with a hole: junctions, end points and arcs.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/junction_graph.py [OUT.vtp]
Prints every junction with its radius and governor count, and the arc counts.
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

frame = medialaxis.vtkMedialShapeSource()
frame.SetShapeToSquareFrame()  # the square [-2, 2]^2 with the hole [-1, 1]^2
junctions = medialaxis.vtkMedialJunctionFilter()
junctions.SetInputConnection(frame.GetOutputPort())
junctions.Update()
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

if len(sys.argv) > 1:
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(graph)
    writer.SetFileName(sys.argv[1])
    writer.Write()
