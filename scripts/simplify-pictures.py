#!/usr/bin/env python3
"""The simplification pictures of docs/how-it-works/simplification.md, rendered offscreen
with vtkMedialScene:
fandisk simplified to 500 balls (its medial mesh in the translucent original, and the
envelope beside it), and the horse's medial mesh before and after simplification to 100
balls (each with its envelope).

  xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
      scripts/simplify-pictures.py [METHOD] [MESH_DIR] [OUT_DIR]

METHOD is quadric (default) or coverage; MESH_DIR defaults to ../shared/data/meshes,
OUT_DIR to docs/images.
"""
import os
import sys

import medialaxis

method = sys.argv[1] if len(sys.argv) > 1 else "quadric"
mesh_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "shared",
                                                               "data", "meshes")
out_dir = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(__file__), "..", "docs", "images")
methods = {"quadric": medialaxis.vtkMedialSimplifyFilter.QUADRIC,
           "coverage": medialaxis.vtkMedialSimplifyFilter.COVERAGE}


def read(name):
    reader = medialaxis.vtkMedialFileReader()
    reader.SetFileName(os.path.join(mesh_dir, name))
    reader.Update()
    return reader.GetOutput()


def medial_mesh(surface):
    sampler = medialaxis.vtkMedialAxisSampler()
    sampler.SetInputData(surface)
    mesh = medialaxis.vtkMedialMeshFilter()
    mesh.SetInputData(surface)
    mesh.SetBallsConnection(sampler.GetOutputPort())
    mesh.Update()
    return mesh.GetOutput()


def simplify(mesh, surface, k):
    simplifier = medialaxis.vtkMedialSimplifyFilter()
    simplifier.SetInputData(mesh)
    simplifier.SetSurfaceData(surface)
    simplifier.SetMethod(methods[method])
    simplifier.SetNumberOfBalls(k)
    simplifier.Update()
    return simplifier.GetOutput()


def envelope(mesh):
    union = medialaxis.vtkMedialBallUnion()
    union.SetInputData(mesh)
    union.SetPrimitives(medialaxis.vtkMedialBallUnion.MEDIAL_MESH)
    union.SetSampleDimensions(128, 128, 128)
    union.Update()
    return union.GetOutput()


def picture(surface, mesh, name, size=(1000, 380)):
    scene = medialaxis.vtkMedialScene()
    scene.SetSurface(surface)
    scene.SetMedial(mesh)
    scene.SetReconstruction(envelope(mesh))
    scene.SetWindowSize(*size)
    scene.SetPointSize(4)
    if not scene.WritePNG(os.path.join(out_dir, name)):
        sys.exit("cannot write " + name)
    print(name, mesh.GetNumberOfPoints(), "balls")


fandisk = read("fandisk.obj")
picture(fandisk, simplify(medial_mesh(fandisk), fandisk, 500), "fandisk-k500.png")
horse = read("horse.ply")
horse_mesh = medial_mesh(horse)
picture(horse, horse_mesh, "horse-unsimplified.png")
picture(horse, simplify(horse_mesh, horse, 100), "horse-k100.png")
