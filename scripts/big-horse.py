#!/usr/bin/python3
"""Writes horse.ply Loop-subdivided twice (about 1.55 M triangles, as medial-bench builds
it), for the limit runs of scripts/limits.py and the 1M-ball command line.
   big-horse.py HORSE.ply OUT.vtp [--raw] [--linear]    or    big-horse.py HORSE.ply OUT.ply [--linear]
--linear: linear subdivision instead of Loop's, which keeps horse.ply's 4 crossing triangle pairs
(as 4 times 16 crossing pairs of smaller triangles): the large self-intersecting shell of the repair's
benchmark (issue 38; Loop's smoothing removes the crossings).
.vtp default: binary, zlib-compressed (35 MB). --raw: appended raw binary, uncompressed (68 MB),
which vtkXMLPolyDataReader reads about 2.3 times faster (measured on the 2-core machine, issue 18).
.ply: binary little-endian PLY with float vertices (29 MB), the layout the command line reads
directly (issue 37), as a user would have it."""
import sys
from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersModeling import vtkLinearSubdivisionFilter, vtkLoopSubdivisionFilter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])
triangles = vtkTriangleFilter()
triangles.SetInputConnection(reader.GetOutputPort())
loop = vtkLinearSubdivisionFilter() if "--linear" in sys.argv[3:] else vtkLoopSubdivisionFilter()
loop.SetInputConnection(triangles.GetOutputPort())
loop.SetNumberOfSubdivisions(2)
if sys.argv[2].lower().endswith(".ply"):
    writer = vtkPLYWriter()
    writer.SetFileTypeToBinary()
else:
    writer = vtkXMLPolyDataWriter()
    if "--raw" in sys.argv[3:]:
        writer.SetDataModeToAppended()
        writer.EncodeAppendedDataOff()
        writer.SetCompressorTypeToNone()
    else:
        writer.SetDataModeToBinary()
writer.SetInputConnection(loop.GetOutputPort())
writer.SetFileName(sys.argv[2])
if not writer.Write():
    sys.exit("big-horse.py: cannot write " + sys.argv[2])
print("%s: %d triangles" % (sys.argv[2], loop.GetOutput().GetNumberOfCells()))
