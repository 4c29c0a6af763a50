#!/usr/bin/python3
"""Times vtkMedialJunctionFilter on large polygons (not a test: prints figures).

Usage: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 scripts/junction-timing.py [THREADS]

Polygons: the STAR shape of vtkMedialShapeSource with 1024 spikes (2,048 vertices),
a random star of 10,000 vertices, and a horizontal slice of the shared horse mesh
(vtkCutter + vtkStripper, when ../shared/data/meshes/horse.ply exists). Each is run
three times; the best wall time is printed with the junction and end counts.
"""
import math
import os
import random
import sys
import time

import vtk
import medialaxis  # noqa: F401 (registers the classes)
from medialaxis import vtkMedialJunctionFilter, vtkMedialShapeSource

threads = int(sys.argv[1]) if len(sys.argv) > 1 else 2


def polygon(points):
    pts = vtk.vtkPoints()
    pts.SetDataTypeToDouble()
    cells = vtk.vtkCellArray()
    cells.InsertNextCell(len(points))
    for x, y in points:
        cells.InsertCellPoint(pts.InsertNextPoint(x, y, 0.0))
    pd = vtk.vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    return pd


def shape_star():
    s = vtkMedialShapeSource()
    s.SetShape(vtkMedialShapeSource.STAR)
    s.SetResolution(1024)
    s.Update()
    return s.GetOutput()


def random_star(n=10000, seed=7):
    rng = random.Random(seed)
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    radii = [0.4 + 0.6 * rng.random() for _ in range(n)]
    return polygon([(r * math.cos(a), r * math.sin(a)) for a, r in zip(angles, radii)])


def horse_slice():
    path = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data", "meshes", "horse.ply")
    if not os.path.exists(path):
        return None
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    b = reader.GetOutput().GetBounds()
    plane = vtk.vtkPlane()
    plane.SetOrigin(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]))
    plane.SetNormal(0, 0, 1)
    cut = vtk.vtkCutter()
    cut.SetCutFunction(plane)
    cut.SetInputConnection(reader.GetOutputPort())
    strip = vtk.vtkStripper()
    strip.SetInputConnection(cut.GetOutputPort())
    strip.JoinContiguousSegmentsOn()
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(strip.GetOutputPort())
    clean.Update()
    out = vtk.vtkPolyData()
    out.DeepCopy(clean.GetOutput())  # independent of the pipeline objects going out of scope
    return out


def graph_cycles(graph):
    """Independent cycles of the medial graph (equals the number of holes when correct)."""
    parent = {}

    def root(x):
        parent.setdefault(x, x)
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    nodes = set()
    lines = graph.GetLines()
    lines.InitTraversal()
    ids = vtk.vtkIdList()
    while lines.GetNextCell(ids):
        a, b = ids.GetId(0), ids.GetId(ids.GetNumberOfIds() - 1)
        nodes.update((a, b))
        parent[root(a)] = root(b)
    components = len({root(n) for n in nodes})
    return graph.GetNumberOfLines() - len(nodes) + components, components


for name, make in (("STAR shape (1024 spikes)", shape_star), ("random star", random_star), ("horse slice", horse_slice)):
    data = make()
    if data is None:
        print(f"{name}: skipped (no mesh)")
        continue
    best = None
    for _ in range(3):
        f = vtkMedialJunctionFilter()
        f.SetNumberOfThreads(threads)
        f.SetInputData(data)
        t0 = time.perf_counter()
        f.Update()
        dt = time.perf_counter() - t0
        best = dt if best is None else min(best, dt)
    print(f"{name}: {data.GetNumberOfPoints()} vertices, {threads} threads: {best:.3f} s, "
          f"{f.GetNumberOfJunctions()} junctions, {f.GetNumberOfEndPoints()} ends, "
          f"{f.GetNumberOfBoundarySamples()} samples, unresolved {f.GetUnresolvedIntervals()}, "
          f"{f.GetOutput().GetNumberOfLines()} arcs, (cycles, components) = {graph_cycles(f.GetOutput())}")
