#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Process CPU and wall time of each stage of vtkMedialMeshFilter (and of the sampling).

usage: /usr/bin/python3 scripts/medial-mesh-stages.py PYTHONPATH SURFACE SAMPLES THREADS [SEED] [--no-exact]
       [--repair=none]

PYTHONPATH is the build's package folder (build/lib/python3/dist-packages). The stages are the
filter's progress texts and its ball classifier's; a stage ends where the next one begins.
CPU time (time.process_time, all threads) is the figure to compare on a shared machine.
--no-exact: the classifier without its exact seam and junction balls.
--repair=none: neither the sampler nor the mesh filter checks or repairs the surface (RepairMode
NONE), so that the mesh filter's own stages are timed without the repair's.
"""
import os
import sys
import time


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) < 4:
        sys.exit(__doc__)
    sys.path.insert(0, args[0])
    import medialaxis
    from vtkmodules.vtkCommonCore import vtkCommand

    path, samples, threads = args[1], int(args[2]), int(args[3])
    seed = int(args[4]) if len(args) > 4 else 1
    if path.endswith(".vtp"):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

        reader = vtkXMLPolyDataReader()
    else:
        reader = medialaxis.vtkMedialFileReader()
    reader.SetFileName(path)
    reader.Update()
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputData(reader.GetOutput())
    sampler.SetNumberOfSamples(samples)
    sampler.SetNumberOfThreads(threads)
    sampler.SetRandomSeed(seed)
    no_repair = "--repair=none" in sys.argv
    if no_repair:
        sampler.SetRepairMode(medialaxis.vtkMedialRepairFilter.NONE)
    cpu, wall = time.process_time(), time.time()
    sampler.Update()
    sampling = (time.process_time() - cpu, time.time() - wall)

    mesh = medialaxis.vtkMedialMeshFilter()
    mesh.SetInputData(reader.GetOutput())
    mesh.SetBallsConnection(sampler.GetOutputPort())
    mesh.SetNumberOfThreads(threads)
    if no_repair:
        mesh.SetRepairMode(medialaxis.vtkMedialRepairFilter.NONE)
    stages = []  # [text, cpu, wall] in order of first appearance, summed over returns
    current = {"text": None, "cpu": 0.0, "wall": 0.0}

    def close(now_cpu, now_wall):
        if current["text"] is None:
            return
        for row in stages:
            if row[0] == current["text"]:
                row[1] += now_cpu - current["cpu"]
                row[2] += now_wall - current["wall"]
                return
        stages.append([current["text"], now_cpu - current["cpu"], now_wall - current["wall"]])

    def progress(caller, event):
        text = caller.GetProgressText()
        if text != current["text"]:
            now_cpu, now_wall = time.process_time(), time.time()
            close(now_cpu, now_wall)
            current.update(text=text, cpu=now_cpu, wall=now_wall)

    mesh.AddObserver(vtkCommand.ProgressEvent, progress)
    classifier = mesh.GetClassifier()
    if classifier:
        classifier.AddObserver(vtkCommand.ProgressEvent, progress)
        if "--no-exact" in sys.argv:
            classifier.SetComputeExactPoints(False)
    cpu, wall = time.process_time(), time.time()
    mesh.Update()
    total = (time.process_time() - cpu, time.time() - wall)
    close(time.process_time(), time.time())

    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    print("%s, %d samples, %d threads, seed %d, repair %s, load %s"
          % (os.path.basename(path), samples, threads, seed, "none" if no_repair else "default", load))
    print("  %-40s %9s %9s" % ("stage", "cpu_s", "wall_s"))
    print("  %-40s %9.2f %9.2f" % ("sampling", sampling[0], sampling[1]))
    for text, c, w in stages:
        if c >= 0.005 or w >= 0.005:
            print("  %-40s %9.2f %9.2f" % (text, c, w))
    print("  %-40s %9.2f %9.2f" % ("medial mesh in all", total[0], total[1]))
    print("  ratio to the sampling: %.2f (CPU), %.2f (wall); chi %d, %d component(s)"
          % (total[0] / sampling[0], total[1] / sampling[1], mesh.GetEulerCharacteristic(),
             mesh.GetNumberOfComponents()))


if __name__ == "__main__":
    main()
