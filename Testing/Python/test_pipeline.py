#!/usr/bin/env python3
"""Python pipeline test: stock VTK readers and writers around the medial sampler,
numpy arrays, and one rendered image compared against a baseline.

Arguments: BASELINE_PNG TEMP_DIR. Exits 0 on success, 1 on failure.
"""
import os
import sys

import numpy as np

import medialaxis
from checks import check, finish
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkTestingRendering import vtkTesting

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "Examples", "Python"))
import medial_axis_png  # noqa: E402

baseline, temp = sys.argv[1], sys.argv[2]
os.makedirs(temp, exist_ok=True)
# A capsule written to PLY and read back by VTK's reader feeds the sampler.
capsule = medialaxis.vtkMedialShapeSource()
capsule.SetShapeToCapsule()
capsule.SetRadius(0.5)
capsule.SetLength(2.0)
capsule.SetResolution(24)
ply_path = os.path.join(temp, "capsule.ply")
ply = vtkPLYWriter()
ply.SetInputConnection(capsule.GetOutputPort())
ply.SetFileName(ply_path)
ply.Write()
reader = vtkPLYReader()
reader.SetFileName(ply_path)
sampler = medialaxis.vtkMedialAxisSampler()
sampler.SetInputConnection(reader.GetOutputPort())
sampler.SetNumberOfSamples(3000)
sampler.SetRandomSeed(5)
vtp_path = os.path.join(temp, "capsule-medial.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(sampler.GetOutputPort())
writer.SetFileName(vtp_path)
check(writer.Write() == 1, "pipeline PLY reader -> sampler -> XML writer ran")

back = vtkXMLPolyDataReader()
back.SetFileName(vtp_path)
back.Update()
medial = back.GetOutput()
radius = vtk_to_numpy(medial.GetPointData().GetArray("Radius"))
centres = vtk_to_numpy(medial.GetPoints().GetData())
surface = vtk_to_numpy(medial.GetPointData().GetArray("SurfacePoint"))
check(radius.shape == (3000,), f"3000 radii read back as numpy ({radius.shape})")
axis = np.hypot(centres[:, 0], centres[:, 1])
facet = 2 * np.pi * 0.5 / (4 * 24)
check(axis.max() <= 2 * facet, f"centres on the axis: max offset {axis.max():.4f} <= {2 * facet:.4f}")
body = np.abs(surface[:, 2]) <= 1.0
check(np.abs(radius[body] - 0.5).max() <= 1.5 * facet,
      f"body radii equal the capsule radius: max error {np.abs(radius[body] - 0.5).max():.4f}")
# Tangent at the surface point, unless shrunk to be inscribed: then the centre is farther.
tangent = (np.linalg.norm(centres - surface, axis=1) - radius).min()
check(tangent > -1e-12, f"no ball reaches past its surface point ({tangent:.2e})")
field = medial.GetFieldData()
check(field.GetArray("DiscardedSamples").GetValue(0) == 0, "closed capsule: no discarded samples")

# The reader chosen by the extension, from Python: the same capsule as VTK's PLY reader.
check(medialaxis.vtkMedialFileReader.GetExtensions(medialaxis.vtkMedialFileReader.SURFACE)
      == ".vtp .vtk .ply .stl .obj .off", "vtkMedialFileReader lists the surface extensions")
stock = medialaxis.vtkMedialFileReader.NewReader(ply_path, medialaxis.vtkMedialFileReader.SURFACE)
check(stock is not None and stock.GetClassName() == "vtkPLYReader", "NewReader gives vtkPLYReader for .ply")
any_reader = medialaxis.vtkMedialFileReader()
any_reader.SetFileName(ply_path)
any_reader.Update()
check(any_reader.GetOutput().GetNumberOfPoints() == reader.GetOutput().GetNumberOfPoints() > 0,
      f"vtkMedialFileReader reads {any_reader.GetOutput().GetNumberOfPoints()} points")

# The ball protrusion from Python: exact balls (theta = 0) stay inside the capsule.
exact = medialaxis.vtkMedialAxisSampler()
exact.SetInputConnection(reader.GetOutputPort())
exact.SetNumberOfSamples(1000)
exact.SetMinimumSeparationAngle(0)
protrusion = medialaxis.vtkMedialBallProtrusion()
protrusion.SetSurfaceConnection(reader.GetOutputPort())
protrusion.SetBallsConnection(exact.GetOutputPort())
protrusion.Update()
per_ball = vtk_to_numpy(protrusion.GetOutput().GetPointData().GetArray("Protrusion"))
check(per_ball.shape == (1000,) and protrusion.GetMaxProtrusion() < 1e-9,
      f"theta = 0 balls do not cross the surface (max protrusion {protrusion.GetMaxProtrusion():.2e})")
check(any_reader.GetReadDirectly(), "the capsule's binary PLY is read directly")

# The sampler's own measure of the protrusion (MeasureProtrusion) against the exact pass
# over its balls (MaximumOnly), without shrinking (the angle rule alone crosses the surface).
crossing = medialaxis.vtkMedialAxisSampler()
crossing.SetInputConnection(reader.GetOutputPort())
crossing.SetNumberOfSamples(2000)
crossing.SetMaximumProtrusion(1)
crossing.MeasureProtrusionOn()
crossing.Update()
exact_pass = medialaxis.vtkMedialBallProtrusion()
exact_pass.SetSurfaceConnection(reader.GetOutputPort())
exact_pass.SetBallsConnection(crossing.GetOutputPort())
exact_pass.MaximumOnlyOn()
exact_pass.Update()
own = crossing.GetOutput().GetFieldData().GetArray("MaxProtrusion").GetValue(0)
check(own == crossing.GetMaxProtrusion() > 1e-4 and abs(own - exact_pass.GetMaxProtrusion()) < 1e-11,
      f"the sampler's protrusion {own:.6g} is the exact one {exact_pass.GetMaxProtrusion():.6g}")
check(exact_pass.GetOutput().GetPointData().GetArray("Protrusion") is None, "MaximumOnly: no per-ball array")

# Same seed, same output from Python with 1 and 2 threads.
for threads in (1, 2):
    sampler.SetNumberOfThreads(threads)
    sampler.Update()
    if threads == 1:
        first = vtk_to_numpy(sampler.GetOutput().GetPointData().GetArray("Radius")).copy()
check(np.array_equal(first, vtk_to_numpy(sampler.GetOutput().GetPointData().GetArray("Radius"))),
      "1 and 2 threads give identical radii")

# The methods and the sampling strategies from Python: one-pass (the default) agrees
# with bisection, and face-distance reaches a coverage tolerance with links-free output.
bisection = medialaxis.vtkMedialAxisSampler()
bisection.SetInputConnection(reader.GetOutputPort())
bisection.SetNumberOfSamples(3000)
bisection.SetRandomSeed(5)
bisection.SetMethodToBisection()
bisection.Update()
check(sampler.GetMethod() == medialaxis.vtkMedialAxisSampler.ONE_PASS, "one-pass is the default method")
diagonal = medial.GetLength()
agree = np.mean(np.abs(vtk_to_numpy(bisection.GetOutput().GetPointData().GetArray("Radius")) - first) <= 1e-5 * diagonal)
check(agree >= 0.995, f"one-pass agrees with bisection within 1e-5 of the diagonal on {100 * agree:.2f}% of samples")
covered = medialaxis.vtkMedialAxisSampler()
covered.SetInputConnection(reader.GetOutputPort())
covered.SetSamplingStrategyToFaceDistance()
covered.SetCoverageTolerance(0.01)
covered.SetNumberOfSamples(20000)
covered.Update()
covered_field = covered.GetOutput().GetFieldData()
check(covered_field.GetArray("CoverageReached").GetValue(0) == 1,
      f"face-distance reaches 1% coverage with {covered.GetOutput().GetNumberOfPoints()} balls "
      f"(gap {covered_field.GetArray('MaxCoverageGap').GetValue(0):.4f})")

# 2D or 3D, asked from Python as the command line asks it.
Sampler = medialaxis.vtkMedialAxisSampler
lshape = medialaxis.vtkMedialShapeSource()
lshape.SetShapeToLShape()
lshape.Update()
plane_centre, plane_normal = [0.0] * 3, [0.0] * 3
check(Sampler.IsPlanarInput(lshape.GetOutput(), plane_centre, plane_normal) and abs(plane_normal[2]) > 0.999999,
      f"the L-shape is planar input, normal {plane_normal}")
check(not Sampler.IsPlanarInput(reader.GetOutput()), "the capsule is not planar input")

# One rendered image against its baseline.
demo = medialaxis.vtkMedialShapeSource()
demo_sampler = medialaxis.vtkMedialAxisSampler()
demo_sampler.SetInputConnection(demo.GetOutputPort())
demo_sampler.SetNumberOfSamples(5000)
demo_sampler.Update()
window = medial_axis_png.render(demo.GetOutput(), demo_sampler.GetOutput(), None, size=(400, 300))
testing = vtkTesting()
for arg in ("-V", baseline, "-T", temp):
    testing.AddArgument(arg)
testing.SetRenderWindow(window)
check(testing.RegressionTest(10) == vtkTesting.PASSED, "rendered image matches " + os.path.basename(baseline))

finish()
