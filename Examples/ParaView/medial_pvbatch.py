"""Medial balls of a surface with ParaView's MPI pipeline, gathered into one file.

Usage (pvbatch from scripts/paraview.sh's unpacked ParaView; see docs/paraview.md):
  mpiexec -n R pvbatch Examples/ParaView/medial_pvbatch.py MESH OUT.vtp \\
      [--samples N] [--reconstruct REC.vtp] [--png OUT.png] [--threads T] [--seed S] \\
      [--resolution N] [--plugin MedialAxis.so] [--timing]

MESH is any surface ParaView reads (.ply, .vtp, .stl, .obj, .off, ...) or `demo` for the
built-in demo shape. Every rank reads the whole mesh and solves its share of the
samples (vtkMedialAxisSampler splits the sample indices by piece); the balls of all
ranks are gathered to rank 0 (servermanager.Fetch, a vtkReductionFilter that appends
the pieces) and written to OUT.vtp with their Radius and the other arrays. The
output is the same set of balls for any number of ranks. --reconstruct also writes
the surface of the union of the balls (vtkMedialBallUnion gathers the balls to rank 0
itself). --png renders the balls coloured by radius (needs X: run under xvfb-run).
--timing prints one JSON line with the ranks, threads and wall times.
"""
import argparse
import json
import os
import sys
import time

from paraview import servermanager
from paraview.simple import (
    ColorBy, GetActiveViewOrCreate, LoadPlugin, OpenDataFile, Render, ResetCamera,
    SaveScreenshot, Show)
from paraview.vtk.vtkIOXML import vtkXMLPolyDataWriter


def default_plugin():
    """The plugin built by scripts/paraview.sh, relative to this script."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return os.path.join(root, "build-paraview", "build", "lib", "paraview-5.11", "plugins",
                        "MedialAxis", "MedialAxis.so")


def parse():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh", help="surface file, or 'demo'")
    parser.add_argument("output", help="balls, a .vtp file")
    parser.add_argument("--samples", type=int, default=10000)
    parser.add_argument("--reconstruct", metavar="REC.vtp")
    parser.add_argument("--resolution", type=int, default=128, help="reconstruction grid per axis")
    parser.add_argument("--png", metavar="OUT.png")
    parser.add_argument("--threads", type=int, default=0, help="OpenMP threads per rank, 0: all")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--plugin", default=os.environ.get("MEDIALAXIS_PLUGIN", default_plugin()))
    parser.add_argument("--timing", action="store_true")
    return parser.parse_args()


def write(data, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    if not writer.Write():
        sys.exit("medial_pvbatch: cannot write " + path)


def main():
    args = parse()
    if not os.path.exists(args.plugin):
        sys.exit("medial_pvbatch: no plugin at %s (run scripts/paraview.sh, or pass --plugin)"
                 % args.plugin)
    LoadPlugin(args.plugin, remote=True, ns=globals())
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    times = {}

    start = time.perf_counter()
    if args.mesh == "demo":
        surface = MedialShapeSource()  # noqa: F821 (defined by the plugin)
    else:
        surface = OpenDataFile(args.mesh)
        if surface is None:
            sys.exit("medial_pvbatch: ParaView cannot read " + args.mesh)
    sampler = MedialAxisSampler(  # noqa: F821 (defined by the plugin)
        Input=surface, NumberOfSamples=args.samples, NumberOfThreads=args.threads,
        RandomSeed=args.seed)
    sampler.UpdatePipeline()
    # Rank 0: reading the whole mesh, the preparation, and its share of the samples.
    times["sample_rank0"] = time.perf_counter() - start

    mark = time.perf_counter()
    balls = servermanager.Fetch(sampler)  # every rank's piece, appended on rank 0
    times["gather"] = time.perf_counter() - mark  # waits for the slowest rank, then gathers
    times["sample_and_gather"] = time.perf_counter() - start
    write(balls, args.output)
    print("medial_pvbatch: %d balls from %d rank(s) -> %s"
          % (balls.GetNumberOfPoints(), ranks, args.output))

    if args.reconstruct:
        mark = time.perf_counter()
        union = MedialBallUnion(Input=sampler,  # noqa: F821 (defined by the plugin)
                                SampleDimensions=[args.resolution] * 3)
        rebuilt = servermanager.Fetch(union)
        times["reconstruct"] = time.perf_counter() - mark
        write(rebuilt, args.reconstruct)
        print("medial_pvbatch: union of balls, %d triangles -> %s"
              % (rebuilt.GetNumberOfCells(), args.reconstruct))

    if args.png:
        view = GetActiveViewOrCreate("RenderView")
        view.ViewSize = [800, 600]
        view.OrientationAxesVisibility = 0
        # Points only: a translucent surface needs ordered compositing, whose data
        # redistribution fails in Debian's ParaView 5.11 with more than one rank.
        display = Show(sampler, view)
        display.SetRepresentationType("Points")
        display.PointSize = 3
        ColorBy(display, ("POINTS", "Radius"))
        display.SetScalarBarVisibility(view, True)
        view.CameraPosition = [3, 2.5, 6]
        view.CameraViewUp = [0, 1, 0]
        ResetCamera(view)
        Render(view)
        SaveScreenshot(args.png, view, ImageResolution=[800, 600])
        print("medial_pvbatch: picture -> " + args.png)

    if args.timing:
        print(json.dumps({"ranks": ranks, "threads": args.threads, "samples": args.samples,
                          "balls": balls.GetNumberOfPoints(),
                          **{k: round(v, 3) for k, v in times.items()}}))


main()
