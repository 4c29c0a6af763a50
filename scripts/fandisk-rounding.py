#!/usr/bin/env python3
"""Measures how much the union of medial balls rounds off fandisk's sharp edges.

Samples fandisk with vtkMedialAxisSampler (defaults, bisection, all cores), rebuilds
it with vtkMedialBallUnion at each resolution, and prints the distance from the
original vertices to the reconstruction, separately for vertices on sharp edges
(dihedral angle above 30 degrees) and for the others, in % of the bounding-box
diagonal and in voxels. Run from the build tree's parent:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 scripts/fandisk-rounding.py \
      [MESH] [SAMPLES,...] [MIN_ANGLE]
MIN_ANGLE (the sampler's MinimumSeparationAngle, default 60) = 0 keeps every ball inside
the surface, which separates the rounding from balls that cross mild edges.
"""
import sys

import numpy as np

import medialaxis
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges, vtkTriangleFilter

MESH = sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data/meshes/fandisk.obj"
SAMPLES = [int(s) for s in sys.argv[2].split(",")] if len(sys.argv) > 2 else [10000, 100000]
MIN_ANGLE = float(sys.argv[3]) if len(sys.argv) > 3 else None
RESOLUTIONS = [128, 256]

reader = medialaxis.vtkMedialFileReader()
reader.SetFileName(MESH)
clean = vtkCleanPolyData()
clean.SetInputConnection(reader.GetOutputPort())
triangles = vtkTriangleFilter()
triangles.SetInputConnection(clean.GetOutputPort())
triangles.Update()
mesh = triangles.GetOutput()
diagonal = mesh.GetLength()

# Sharp-edge vertices: end points of feature edges.
features = vtkFeatureEdges()
features.SetInputData(mesh)
features.BoundaryEdgesOff()
features.NonManifoldEdgesOff()
features.ManifoldEdgesOff()
features.FeatureEdgesOn()
features.SetFeatureAngle(30.0)
features.Update()
points = vtk_to_numpy(mesh.GetPoints().GetData())
sharp_points = vtk_to_numpy(features.GetOutput().GetPoints().GetData())
sharp_set = {tuple(p) for p in sharp_points}
sharp = np.array([tuple(p) in sharp_set for p in points])


def distances_to(reconstruction):
    """Distance from every vertex of the mesh to the reconstruction (vtkMedialReconstructionError)."""
    error = medialaxis.vtkMedialReconstructionError()
    error.SetOriginalData(mesh)
    error.SetReconstructionData(reconstruction)
    error.SetNumberOfAreaSamples(0)  # the vertex distances only
    error.Update()
    return vtk_to_numpy(error.GetOutput(1).GetPointData().GetArray("SurfaceDistance"))


theta = MIN_ANGLE if MIN_ANGLE is not None else medialaxis.vtkMedialAxisSampler().GetMinimumSeparationAngle()
print(f"{MESH}: {mesh.GetNumberOfCells()} triangles, {sharp.sum()} of {len(points)} vertices on sharp edges, "
      f"min angle {theta:g}; distances from original vertices to the reconstruction")
print("| samples | grid | voxel % | sharp max % | sharp median % | sharp max voxels | other max % | other median % |")
print("|---|---|---|---|---|---|---|---|")
for count in SAMPLES:
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputData(mesh)
    sampler.SetNumberOfSamples(count)
    sampler.SetMethodToBisection()
    if MIN_ANGLE is not None:
        sampler.SetMinimumSeparationAngle(MIN_ANGLE)
    for n in RESOLUTIONS:
        union = medialaxis.vtkMedialBallUnion()
        union.SetInputConnection(sampler.GetOutputPort())
        union.SetSampleDimensions(n, n, n)
        union.Update()
        d = distances_to(union.GetOutput()) / diagonal * 100
        voxel = union.GetVoxelSize() / diagonal * 100
        print(f"| {count} | {n}^3 | {voxel:.3f} | {d[sharp].max():.3f} | {np.median(d[sharp]):.3f} | "
              f"{d[sharp].max() / voxel:.1f} | {d[~sharp].max():.3f} | {np.median(d[~sharp]):.4f} |")
