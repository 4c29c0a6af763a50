#!/usr/bin/env python3
"""vtkMedialThickness on a mesh (default: the shared horse.ply), three runs of every vertex and
three of every vertex and cell, 2 threads: processor time (user + system, both threads) and
wall time of each Update. Compare two builds on a shared machine by their processor times.
The filter runs with RepairMode NONE, so that the figure is the thickness's own: horse.ply is
not a valid solid (4 intersecting triangle pairs), and the default AUTO would repair it in every
run (docs/repair.md). MEDIALAXIS_REPAIR=auto times the default instead.

    /usr/bin/python3 scripts/thickness-timing.py BUILD_DIR [MESH]
"""
import os
import resource
import sys
import time

build = sys.argv[1] if len(sys.argv) > 1 else "build"
mesh = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data",
                                                          "meshes", "horse.ply")
sys.path.insert(0, os.path.join(build, "lib", "python3", "dist-packages"))
import medialaxis  # noqa: E402


def cpu():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


reader = medialaxis.vtkMedialFileReader()
reader.SetFileName(mesh)
reader.Update()
for cells in (False, True):
    runs = []
    for _ in range(3):
        wall = medialaxis.vtkMedialThickness()
        wall.SetInputData(reader.GetOutput())
        wall.SetNumberOfThreads(2)
        wall.SetComputeCellThickness(cells)
        if hasattr(wall, "SetRepairMode"):  # builds before the repair have no RepairMode
            wall.SetRepairMode(0 if os.environ.get("MEDIALAXIS_REPAIR") == "auto" else 1)
        c0, w0 = cpu(), time.time()
        wall.Update()
        runs.append((cpu() - c0, time.time() - w0))
    print("%s: CPU s %s; wall s %s" % ("every vertex and cell" if cells else "every vertex",
                                        ", ".join("%.3f" % r[0] for r in runs), ", ".join("%.3f" % r[1] for r in runs)))
