#!/usr/bin/python3
"""Writes a mesh as an unwelded triangle soup, as some exporters save it: every triangle gets
its own three corners, each coordinate moved by a uniform jitter of +-J times the diagonal
(seeded, so the file is the same every time). The repair's weld (issue 38) must weld it back.
   triangle-soup.py IN.{ply,obj,vtp} OUT.vtp [J (default 1e-7)]
Points are written in double precision (binary, zlib-compressed .vtp)."""
import sys
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

name = sys.argv[1]
reader = vtkPLYReader() if name.endswith('.ply') else vtkOBJReader() if name.endswith('.obj') else vtkXMLPolyDataReader()
reader.SetFileName(name)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(reader.GetOutputPort())
triangles.Update()
mesh = triangles.GetOutput()
x = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
corners = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1)
jitter = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-7
soup = x[corners] + np.random.default_rng(7).uniform(-1.0, 1.0, (corners.size, 3)) * jitter * mesh.GetLength()
points = vtkPoints()
points.SetData(numpy_to_vtk(soup, deep=1))
cells = vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, corners.size + 1, 3, dtype=np.int64), deep=1),
              numpy_to_vtkIdTypeArray(np.arange(corners.size, dtype=np.int64), deep=1))
out = vtkPolyData()
out.SetPoints(points)
out.SetPolys(cells)
writer = vtkXMLPolyDataWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputData(out)
writer.SetCompressorTypeToZLib()
writer.Write()
print(f'{corners.size // 3} triangles, {corners.size} points, jitter {jitter} of the diagonal {mesh.GetLength():.6g}')
