"""pvpython smoke test of the MedialAxis plugin: it loads, every proxy works, the file types
are registered, the radius array selection reaches the filter, and sampler ->
reconstruction runs on the demo shape.

Usage: pvpython test_plugin.py MedialAxis.so SCRATCH_DIR
Prints one line per check and "FAIL ..." (exit 1) on the first failure.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import Calculator, LoadPlugin, OpenDataFile, SaveData

plugin, scratch = sys.argv[1], sys.argv[2]
os.makedirs(scratch, exist_ok=True)


def check(condition, message):
    if not condition:
        print("FAIL " + message)
        sys.exit(1)
    print("ok   " + message)


LoadPlugin(plugin, remote=False, ns=globals())
check(all(name in globals() for name in (
    "MedialAxisSampler", "MedialDenoise", "MedialJunctionFilter", "MedialBallUnion", "MedialShapeSource",
    "MedialReconstructionError", "MedialBallProtrusion", "MedialBallClassifier", "MedialThickness", "MedialMesh", "MedialPrune", "MedialScaleAxis", "MedialSimplify",
    "MedialMeshReader", "MedialOFFReader", "MedialBallPLYReader", "MedialBallCSVReader")),
      "the plugin defines every proxy")

# Sampler -> reconstruction on the demo shape.
demo = MedialShapeSource()  # noqa: F821 (defined by the plugin)
sampler = MedialAxisSampler(Input=demo, NumberOfSamples=3000)  # noqa: F821
sampler.UpdatePipeline()
balls = servermanager.Fetch(sampler)
check(balls.GetNumberOfPoints() == 3000 and balls.GetPointData().GetArray("Radius") is not None,
      "sampler: %d balls with Radius" % balls.GetNumberOfPoints())
union = MedialBallUnion(Input=sampler, SampleDimensions=[64, 64, 64])  # noqa: F821
rebuilt = servermanager.Fetch(union)
check(rebuilt.GetNumberOfCells() > 1000, "reconstruction: %d triangles" % rebuilt.GetNumberOfCells())
doubled = Calculator(Input=sampler, ResultArrayName="R2", Function="2*Radius")  # noqa: F821
union_doubled = MedialBallUnion(Input=doubled, SampleDimensions=[64, 64, 64], Radius=["POINTS", "R2"])  # noqa: F821
bigger = servermanager.Fetch(union_doubled).GetBounds()
check(bigger[1] - bigger[0] > rebuilt.GetBounds()[1] - rebuilt.GetBounds()[0],
      "reconstruction: the Radius array selection reaches the filter (2 x Radius is wider)")

# The measures: the reconstruction's error against the demo shape, and the balls'
# protrusion with the radius array chosen in the array selection (a renamed copy of
# Radius gives the same figure; another array gives another one).
error = MedialReconstructionError(Original=demo, Reconstruction=union,  # noqa: F821
                                  NumberOfAreaSamples=2000)
measured = servermanager.Fetch(error)
hausdorff = measured.GetFieldData().GetArray("VertexMaxError")
check(hausdorff is not None and 0 < max(hausdorff.GetTuple2(0)) < 0.05,
      "reconstruction error: vertex Hausdorff %s of the diagonal"
      % (hausdorff.GetTuple2(0) if hausdorff else None,))
renamed = Calculator(Input=sampler, ResultArrayName="R2", Function="Radius")  # noqa: F821
protrusion = MedialBallProtrusion(Surface=demo, Balls=sampler)  # noqa: F821
by_radius = servermanager.Fetch(protrusion).GetFieldData().GetArray("MaxProtrusion").GetValue(0)
protrusion.Balls = renamed
protrusion.Radius = ["POINTS", "R2"]
by_copy = servermanager.Fetch(protrusion).GetFieldData().GetArray("MaxProtrusion").GetValue(0)
protrusion.Radius = ["POINTS", "SeparationAngle"]
by_angle = servermanager.Fetch(protrusion).GetFieldData().GetArray("MaxProtrusion").GetValue(0)
check(by_radius == by_copy and by_angle != by_radius,
      "protrusion: radius array selection (Radius %g, copy %g, SeparationAngle %g)"
      % (by_radius, by_copy, by_angle))

# Maximum Protrusion reaches the sampler: the angle rule alone (1) lets balls cross the
# demo shape deeper than the inscribed default does.
loose = MedialAxisSampler(Input=demo, NumberOfSamples=3000, MaximumProtrusion=1)  # noqa: F821
loose_protrusion = MedialBallProtrusion(Surface=demo, Balls=loose)  # noqa: F821
by_loose = servermanager.Fetch(loose_protrusion).GetFieldData().GetArray("MaxProtrusion").GetValue(0)
check(by_loose > by_radius, "sampler: Maximum Protrusion 1 crosses deeper (%g) than the default (%g)"
      % (by_loose, by_radius))

# Wall thickness: 2 x TubeRadius on a torus, Radius - InnerRadius on a hollow sphere
# (the new shapes' panels reach the source), and the thin-region figures.
for shape, props, expected in (("Torus", {"Radius": 1.0, "TubeRadius": 0.25, "Resolution": 48}, 0.5),
                               ("Hollow sphere", {"Radius": 1.0, "InnerRadius": 0.6, "Resolution": 4}, 0.4)):
    solid = MedialShapeSource(Shape=shape, **props)  # noqa: F821
    walls = MedialThickness(Input=solid, ThinThreshold=expected * 1.05)  # noqa: F821
    measured = servermanager.Fetch(walls)
    values = measured.GetPointData().GetArray("Thickness")
    low, high = values.GetRange() if values else (0, 0)
    fraction = measured.GetFieldData().GetArray("ThinAreaFraction")
    check(values is not None and abs(low - expected) < 0.02 * expected and abs(high - expected) < 0.02 * expected
          and measured.GetCellData().GetArray("Thickness") is not None
          and fraction is not None and fraction.GetValue(0) > 0.99,
          "thickness of the %s: %g to %g (expected %g), thin area %s"
          % (shape.lower(), low, high, expected, fraction.GetValue(0) if fraction else None))

# The 3D structure: every ball of a box classified, and its exact junction vertices.
box = MedialShapeSource(Shape="Box", Resolution=2)  # noqa: F821
box_balls = MedialAxisSampler(Input=box, NumberOfSamples=2000, MinimumSeparationAngle=0)  # noqa: F821
classifier = MedialBallClassifier(Balls=box_balls, Surface=box, MinimumSeparationAngle=0)  # noqa: F821
classified = servermanager.Fetch(classifier)
exact = servermanager.Fetch(classifier, idx=1)
types = classified.GetPointData().GetArray("MedialPointType")
check(types is not None and classified.GetNumberOfPoints() == 2000 and exact.GetNumberOfPoints() > 0,
      "classifier: 2000 balls typed, %d exact seam and junction points" % exact.GetNumberOfPoints())

# The medial mesh of a torus from the sampler's balls: one component with the solid's
# Euler characteristic 0.
torus = MedialShapeSource(Shape="Torus")  # noqa: F821
torus_balls = MedialAxisSampler(Input=torus, NumberOfSamples=3000)  # noqa: F821
medial_mesh = MedialMesh(Input=torus, Balls=torus_balls)  # noqa: F821
meshed = servermanager.Fetch(medial_mesh)
euler = meshed.GetFieldData().GetArray("EulerCharacteristic")
components = meshed.GetFieldData().GetArray("Components")
check(meshed.GetNumberOfPolys() > 0 and euler is not None and euler.GetValue(0) == 0
      and components is not None and components.GetValue(0) == 1,
      "medial mesh of a torus: %d triangles, Euler characteristic %s, %s component(s)"
      % (meshed.GetNumberOfPolys(), euler.GetValue(0) if euler else None,
         components.GetValue(0) if components else None))

# Simplification to exactly 40 balls keeps the torus's topology; pruning keeps it too.
simplified = servermanager.Fetch(MedialSimplify(Input=medial_mesh, NumberOfBalls=40))  # noqa: F821
simple_euler = simplified.GetFieldData().GetArray("EulerCharacteristic")
check(simplified.GetNumberOfPoints() == 40 and simple_euler is not None and simple_euler.GetValue(0) == 0,
      "simplify: %d balls, Euler characteristic %s" % (simplified.GetNumberOfPoints(),
                                                      simple_euler.GetValue(0) if simple_euler else None))
covered = servermanager.Fetch(MedialSimplify(Input=medial_mesh, Surface=torus, Method="Coverage",  # noqa: F821
                                             NumberOfBalls=40))
check(covered.GetNumberOfPoints() == 40, "simplify by coverage: %d balls" % covered.GetNumberOfPoints())
pruned = servermanager.Fetch(MedialPrune(Input=medial_mesh, Measure="Separation angle"))  # noqa: F821
check(pruned.GetCellData().GetArray("Significance") is not None and 0 < pruned.GetNumberOfPolys(),
      "prune: %d of %d triangles kept, Significance per cell" % (pruned.GetNumberOfPolys(), meshed.GetNumberOfPolys()))

# The scale axis of the torus's balls: fewer balls, each with its Significance, and the
# medial mesh of the kept balls still has the torus's Euler characteristic 0.
scaled_balls = MedialScaleAxis(Input=torus_balls, ScaleFactor=1.5)  # noqa: F821
scaled = servermanager.Fetch(scaled_balls)
scaled_mesh = servermanager.Fetch(MedialMesh(Input=torus, Balls=scaled_balls))  # noqa: F821
scaled_euler = scaled_mesh.GetFieldData().GetArray("EulerCharacteristic")
check(0 < scaled.GetNumberOfPoints() < 3000 and scaled.GetPointData().GetArray("Significance") is not None
      and scaled_euler is not None and scaled_euler.GetValue(0) == 0,
      "scale axis: %d of 3000 balls kept, mesh Euler characteristic %s"
      % (scaled.GetNumberOfPoints(), scaled_euler.GetValue(0) if scaled_euler else None))

# Denoise: the same cells, the points moved, its pass band reaching the filter.
denoised = servermanager.Fetch(MedialDenoise(Input=torus, PassBand=0.05))  # noqa: F821
torus_surface = servermanager.Fetch(torus)
moved = max(abs(denoised.GetPoint(i)[k] - torus_surface.GetPoint(i)[k])
            for i in range(0, torus_surface.GetNumberOfPoints(), 7) for k in range(3))
check(denoised.GetNumberOfPolys() == torus_surface.GetNumberOfPolys() and 0 < moved,
      "denoise: %d triangles, points moved up to %g" % (denoised.GetNumberOfPolys(), moved))

# Enumerations take their labels; the values reach the filter.
sampler.Method = "Bisection"
sampler.SamplingStrategy = "Face distance"
sampler.NumberOfSamples = 500
sampler.RandomSeed = 7
sampler.UpdatePipeline()
check(sampler.GetDataInformation().GetNumberOfPoints() == 500,
      "enumerations: Bisection with Face distance, %d balls"
      % sampler.GetDataInformation().GetNumberOfPoints())

# The 2D graph of a planar demo shape.
frame = MedialShapeSource(Shape="Square frame (2D)")  # noqa: F821
graph = MedialJunctionFilter(Input=frame)  # noqa: F821
graph.UpdatePipeline()
check(graph.GetDataInformation().GetNumberOfCells() == 16,
      "2D graph of the square frame: %d arcs" % graph.GetDataInformation().GetNumberOfCells())

# File types: .ma written by the plugin's writer and read back by its reader; OFF read.
ma = os.path.join(scratch, "balls.ma")
SaveData(ma, proxy=MedialAxisSampler(Input=demo, NumberOfSamples=200))  # noqa: F821
reader = OpenDataFile(ma)
check(reader is not None and reader.GetXMLName() == "MedialMeshReader",
      ".ma opens with %s" % (reader.GetXMLName() if reader else None))
reader.UpdatePipeline()
check(reader.GetDataInformation().GetNumberOfPoints() == 200 and "Radius" in reader.PointData.keys(),
      ".ma round trip: %d balls" % reader.GetDataInformation().GetNumberOfPoints())
# PLY and CSV balls: the plugin's writers (chosen explicitly: ParaView has its own PLY and
# CSV writers and readers for these extensions) and readers give back the same balls;
# the PLY writer's File Type reaches the writer.
few = MedialAxisSampler(Input=demo, NumberOfSamples=200)  # noqa: F821
written = servermanager.Fetch(few)
for ext, writer, reader, settings in (("ply", "MedialBallPLYWriter", MedialBallPLYReader, {"FileType": "ASCII"}),  # noqa: F821
                                      ("csv", "MedialBallCSVWriter", MedialBallCSVReader, {})):  # noqa: F821
    path = os.path.join(scratch, "balls." + ext)
    getattr(servermanager.writers, writer)(Input=few, FileName=path, **settings).UpdatePipeline()
    back = servermanager.Fetch(reader(FileName=path))
    radii, radii_back = written.GetPointData().GetArray("Radius"), back.GetPointData().GetArray("Radius")
    same = back.GetNumberOfPoints() == 200 and radii_back is not None and all(
        written.GetPoint(i) == back.GetPoint(i) and radii.GetValue(i) == radii_back.GetValue(i) for i in range(200))
    check(same, ".%s balls round trip exactly (%d balls)" % (ext, back.GetNumberOfPoints()))
with open(os.path.join(scratch, "balls.ply"), "rb") as f:
    check(b"format ascii 1.0" in f.read(200), "PLY writer: File Type ASCII reaches the writer")

off = os.path.join(scratch, "cube.off")
with open(off, "w") as f:
    f.write("OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
            "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
cube = OpenDataFile(off)
check(cube is not None and cube.GetXMLName() == "MedialOFFReader",
      ".off opens with %s" % (cube.GetXMLName() if cube else None))
cube_balls = MedialAxisSampler(Input=cube, NumberOfSamples=100)  # noqa: F821
cube_balls.UpdatePipeline()
check(cube_balls.GetDataInformation().GetNumberOfPoints() == 100, "OFF cube -> 100 balls")
print("plugin test passed")
