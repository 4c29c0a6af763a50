#!/usr/bin/env python3
"""Pruning and simplification: the 2D graph of a finely polygonised trefoil pruned to its
3 true branches, the balls of a noisy sphere reduced by the scale axis transform (and the
same after vtkMedialDenoiseFilter smoothed the sphere first), and the medial mesh of the demo
jack simplified to K balls.

Usage (from the build tree):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/prune_simplify.py [K]
Prints the graph's end points and junctions before and after pruning (the Significance
array lets you threshold it yourself), then the simplified mesh's size and topology.
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer


def ends_and_junctions(graph):
    kind = vtk_to_numpy(graph.GetPointData().GetArray("MedialPointType"))
    return int((kind == 0).sum()), int((kind == 2).sum())


trefoil = medialaxis.vtkMedialShapeSource()
trefoil.SetShapeToTrefoil()  # a rounded 3-armed star, 16 * Resolution vertices
trefoil.SetResolution(38)
graph = medialaxis.vtkMedialJunctionFilter()
graph.SetInputConnection(trefoil.GetOutputPort())
prune = medialaxis.vtkMedialPruneFilter()  # default measure and threshold
prune.SetInputConnection(graph.GetOutputPort())
prune.Update()
graph.Update()
before, after = ends_and_junctions(graph.GetOutput()), ends_and_junctions(prune.GetOutput())
significance = vtk_to_numpy(prune.GetOutput().GetCellData().GetArray("Significance"))
print(f"trefoil graph: {before[0]} end points, {before[1]} junctions; pruned "
      f"({medialaxis.vtkMedialPruneFilter.GetMeasureName(prune.GetMeasure())}, threshold "
      f"{prune.GetEffectiveThreshold():g}): {after[0]} end points, {after[1]} junctions, "
      f"{prune.GetNumberOfPrunedBranches()} branches removed, least kept Significance "
      f"{significance.min():.3f}")

# A sphere of radius 1 with Gaussian noise: its medial axis is one point, the noise
# grows branches toward the surface; the scale axis (balls covered at scale 1.5 go)
# keeps the balls near the centre.
sphere = medialaxis.vtkMedialShapeSource()
sphere.SetShapeToSphere()
sphere.SetResolution(4)  # 5120 triangles
sphere.Update()
noisy = sphere.GetOutput().NewInstance()
noisy.DeepCopy(sphere.GetOutput())
points = vtk_to_numpy(noisy.GetPoints().GetData())  # a view: edits change the surface
points += np.random.default_rng(3).normal(0.0, 0.002 * noisy.GetLength(), points.shape)
noisy.GetPoints().Modified()
def scale_axis_of(surface_port, scale):
    """3000 balls of the surface, the scale axis of them, and how far from the centre
    the farthest ball of each reaches."""
    balls = medialaxis.vtkMedialAxisSampler()
    balls.SetInputConnection(surface_port)
    balls.SetNumberOfSamples(3000)
    axis = medialaxis.vtkMedialScaleAxisFilter()
    axis.SetInputConnection(balls.GetOutputPort())
    if scale is not None:
        axis.SetScaleFactor(scale)
    axis.Update()
    reach = [np.max(np.linalg.norm(vtk_to_numpy(b.GetPoints().GetData()), axis=1))
             for b in (balls.GetOutput(), axis.GetOutput())]
    return balls, axis, reach


noisy_source = vtkTrivialProducer()
noisy_source.SetOutput(noisy)
sphere_balls, scale_axis, far = scale_axis_of(noisy_source.GetOutputPort(), None)
print(f"noisy sphere: {sphere_balls.GetOutput().GetNumberOfPoints()} balls reaching {far[0]:.3f} from the "
      f"centre -> {scale_axis.GetOutput().GetNumberOfPoints()} balls within {far[1]:.3f} "
      f"(scale {scale_axis.GetScaleFactor():g}, {scale_axis.GetNumberOfRemovedBalls()} removed)")

# The same noisy sphere smoothed first (vtkMedialDenoiseFilter, as medial-axis --denoise),
# then the scale axis at 1.3 (the scale --denoise --prune uses).
denoise = medialaxis.vtkMedialDenoiseFilter()
denoise.SetInputData(noisy)
smoothed_balls, smoothed_axis, far = scale_axis_of(
    denoise.GetOutputPort(), medialaxis.vtkMedialScaleAxisFilter.GetDenoisedScaleFactor())
print(f"denoised sphere (vertices moved up to {denoise.GetMaximumDisplacement():.4f} of the diagonal): "
      f"balls reaching {far[0]:.3f} from the centre -> {smoothed_axis.GetOutput().GetNumberOfPoints()} balls "
      f"within {far[1]:.3f} (scale {smoothed_axis.GetScaleFactor():g})")

k = int(sys.argv[1]) if len(sys.argv) > 1 else 50
jack = medialaxis.vtkMedialShapeSource()  # the demo solid (JACK)
balls = medialaxis.vtkMedialAxisSampler()
balls.SetInputConnection(jack.GetOutputPort())
balls.SetNumberOfSamples(3000)
mesh = medialaxis.vtkMedialMeshFilter()
mesh.SetInputConnection(jack.GetOutputPort())
mesh.SetBallsConnection(balls.GetOutputPort())
simplify = medialaxis.vtkMedialSimplifyFilter()
simplify.SetInputConnection(mesh.GetOutputPort())
simplify.SetNumberOfBalls(k)
simplify.Update()
out = simplify.GetOutput()
radius = vtk_to_numpy(out.GetPointData().GetArray("Radius"))
print(f"jack medial mesh: {mesh.GetOutput().GetNumberOfPoints()} balls -> {out.GetNumberOfPoints()} balls, "
      f"{out.GetNumberOfPolys()} triangles, Euler characteristic {simplify.GetEulerCharacteristic()}, "
      f"{simplify.GetNumberOfComponents()} component(s), radii {np.min(radius):.3f} to {np.max(radius):.3f}")
