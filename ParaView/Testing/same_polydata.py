"""Exits 0 when two .vtp files hold the same points with the same point data, in any order.

Usage: same_polydata.py A.vtp B.vtp [--min-points N]
Each point is a row: its coordinates, then every point-data array's components (arrays
matched by name). The rows of both files are sorted and compared bit for bit, as are
the numbers of cells. Used to check that 1 and 2 pvbatch ranks give the same balls.
"""
import argparse
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    columns = [vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)] if data.GetPoints() else []
    names = []
    point_data = data.GetPointData()
    for i in sorted(range(point_data.GetNumberOfArrays()), key=point_data.GetArrayName):
        array = vtk_to_numpy(point_data.GetArray(i)).astype(np.float64)
        columns.append(array.reshape(len(array), -1))
        names.append(point_data.GetArrayName(i))
    rows = np.hstack(columns) if columns else np.zeros((0, 3))
    return rows[np.lexsort(rows.T[::-1])], names, data.GetNumberOfCells()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--min-points", type=int, default=1)
    args = parser.parse_args()
    rows_a, names_a, cells_a = read(args.a)
    rows_b, names_b, cells_b = read(args.b)
    problems = []
    if names_a != names_b:
        problems.append("arrays differ: %s against %s" % (names_a, names_b))
    if rows_a.shape != rows_b.shape:
        problems.append("%d points against %d" % (len(rows_a), len(rows_b)))
    elif not np.array_equal(rows_a, rows_b):
        differing = np.count_nonzero(np.any(rows_a != rows_b, axis=1))
        problems.append("%d of %d sorted rows differ" % (differing, len(rows_a)))
    if cells_a != cells_b:
        problems.append("%d cells against %d" % (cells_a, cells_b))
    if len(rows_a) < args.min_points:
        problems.append("only %d points, expected at least %d" % (len(rows_a), args.min_points))
    if problems:
        print("FAIL %s vs %s: %s" % (args.a, args.b, "; ".join(problems)))
        return 1
    print("same: %d points, %d cells, arrays %s" % (len(rows_a), cells_a, ", ".join(names_a)))
    return 0


sys.exit(main())
