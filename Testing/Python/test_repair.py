#!/usr/bin/env python3
"""The repair from Python: vtkMedialRepairFilter on two overlapping spheres (an
un-booleaned union) and on a flat sheet, and the sampler's RepairMode; then the command
line on the same spheres written to a file (--repair, the repair_* members of --stats,
one warning line per step).

Arguments: MEDIAL_AXIS TEMP_DIR. Exits 0 on success, 1 on failure.
"""
import json
import os
import subprocess
import sys

import medialaxis
from checks import check, finish
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

cli, temp = sys.argv[1], sys.argv[2]
os.makedirs(temp, exist_ok=True)

# Two unit spheres whose centres are 1.2 apart, in one surface.
sphere = medialaxis.vtkMedialShapeSource()
sphere.SetShapeToSphere()
sphere.SetResolution(4)
move = vtkTransform()
move.Translate(1.2, 0, 0)
moved = vtkTransformPolyDataFilter()
moved.SetTransform(move)
moved.SetInputConnection(sphere.GetOutputPort())
both = vtkAppendPolyData()
both.AddInputConnection(sphere.GetOutputPort())
both.AddInputConnection(moved.GetOutputPort())
both.Update()

check(medialaxis.vtkMedialRepairFilter.GetModeName(medialaxis.vtkMedialRepairFilter.WRAP) == "wrap"
      and medialaxis.vtkMedialRepairFilter.GetModeFromName("none") == medialaxis.vtkMedialRepairFilter.NONE,
      "the mode names")

repair = medialaxis.vtkMedialRepairFilter()
repair.SetInputConnection(both.GetOutputPort())
repair.ReportStepsOff()
repair.Update()
lines = [repair.GetReportLine(i) for i in range(repair.GetNumberOfReportLines())]
check(repair.GetChanged() and not repair.GetInputWasValid(), "the spheres are repaired: " + "; ".join(lines))
check(any(line.startswith("union:") for line in lines) and repair.GetJoinedShells() == 1, "one union")
field = repair.GetOutput().GetFieldData()
report = field.GetAbstractArray("RepairReport")
check(report is not None and report.GetNumberOfValues() == len(lines), "the report lines are field data")
check(vtk_to_numpy(field.GetArray("RepairJoinedShells"))[0] == 1, "RepairJoinedShells is field data")
# The distance is below the buried depth (1e-3): input just inside the union's crease.
check(repair.GetMaximumDistance() < 1e-3 and 0.05 < repair.GetBuriedArea() < 0.5,
      "the union moved nothing beyond the crease (%g) and buried the caps (%g of the area)"
      % (repair.GetMaximumDistance(), repair.GetBuriedArea()))

# The sampler repairs by default, and its balls reach the union's largest ball.
sampler = medialaxis.vtkMedialAxisSampler()
sampler.SetInputConnection(both.GetOutputPort())
sampler.SetNumberOfSamples(3000)
warnings = []
sampler.AddObserver(vtkCommand.WarningEvent, lambda obj, event: warnings.append(event))
sampler.Update()
radius = vtk_to_numpy(sampler.GetOutput().GetPointData().GetArray("Radius"))
check(sampler.GetSurfaceRepaired() and sampler.GetDiscardedSamples() == 0,
      "the sampler samples the repaired union (%d discarded)" % sampler.GetDiscardedSamples())
check(abs(radius.max() - 1.0) < 0.01, "its largest ball is 1.0 within 1%% (%.4f)" % radius.max())
check(sampler.GetOutput().GetFieldData().GetAbstractArray("RepairReport") is not None,
      "the repair's report joins the balls' field data")
none = medialaxis.vtkMedialAxisSampler()
none.SetInputConnection(both.GetOutputPort())
none.SetNumberOfSamples(3000)
none.SetRepairMode(medialaxis.vtkMedialRepairFilter.NONE)
none.AddObserver(vtkCommand.WarningEvent, lambda obj, event: None)
none.Update()
check(none.GetDiscardedSamples() > 0 and not none.GetSurfaceRepaired(),
      "without the repair, samples are discarded (%d)" % none.GetDiscardedSamples())

# A flat sheet bounds no volume: a clear error, or a thin solid with WRAP.
plane = vtkPlaneSource()
plane.SetResolution(8, 8)
errors = []
sheet = medialaxis.vtkMedialRepairFilter()
sheet.SetInputConnection(plane.GetOutputPort())
sheet.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
sheet.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: None)
sheet.Update()
check(sheet.GetOutput().GetNumberOfCells() == 0, "a flat sheet gives no output")
sheet.SetModeToWrap()
sheet.ReportStepsOff()
sheet.Update()
check(sheet.GetWrapped() and sheet.GetOutput().GetNumberOfCells() > 0, "with WRAP a thin solid")

# The command line: --repair auto (the default) on the spheres' file.
path = os.path.join(temp, "spheres.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(both.GetOutputPort())
writer.SetFileName(path)
writer.Write()
run = subprocess.run([cli, path, "-n", "2000", "--stats", "--quiet"], capture_output=True, text=True)
stats = json.loads(run.stdout)
check(run.returncode == 0 and stats.get("repair") == "auto" and stats.get("repair_unions") == 1
      and stats.get("discarded") == 0, "--stats has the repair's members: " + run.stdout.strip()[:200])
check(any(s.startswith("union:") for s in stats.get("repair_steps", [])), "repair_steps lists the union")
check("Repair: union:" in run.stderr, "one warning line per step on stderr")
plain = subprocess.run([cli, path, "-n", "2000", "--stats", "--quiet", "--repair", "none"],
                       capture_output=True, text=True)
check(plain.returncode == 0 and "repair" not in json.loads(plain.stdout)
      and json.loads(plain.stdout)["discarded"] > 0, "--repair none: today's behaviour")
# The repaired run's file, field data included (RepairBuriedArea), is the same bytes on 1
# and 2 threads.
outputs = []
for threads in ("1", "2"):
    out_path = os.path.join(temp, f"spheres-balls-{threads}.vtp")
    subprocess.run([cli, path, "-n", "2000", "--quiet", "--threads", threads, "-o", out_path], check=True)
    with open(out_path, "rb") as f:
        outputs.append(f.read())
check(outputs[0] == outputs[1], "the repaired run's output is the same bytes on 1 and 2 threads")
finish()
