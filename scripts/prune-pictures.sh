#!/bin/sh
# The pruning pictures of docs/how-it-works/pruning.md, rendered offscreen by the
# command-line program into docs/images/:
#  - 2D: the medial graph of the trefoil (a rounded 3-armed star, 608 vertices) before and
#    after --prune (tubularity): 477 end points become 3;
#  - 3D: the medial mesh of horse.ply with Gaussian noise (sigma 0.1% of the diagonal per
#    coordinate) before and after --prune (the scale axis of the balls), and after
#    --denoise --prune (the surface smoothed first; the picture draws the smoothed surface).
#
#   sh scripts/prune-pictures.sh [BUILD_DIR] [MESH_DIR] [OUT_DIR]
#
# Needs X (run under xvfb-run) and /usr/bin/python3 with Debian's VTK for the noise.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
meshes=${2:-$here/../shared/data/meshes}
out=${3:-$here/docs/images}
cli="$build/bin/medial-axis"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

"$cli" demo:trefoil --junctions "$scratch/t.vtp" --render "$out/prune-2d-before.png" --quiet
"$cli" demo:trefoil --prune --junctions "$scratch/t.vtp" --render "$out/prune-2d-after.png" --quiet

/usr/bin/python3 - "$meshes/horse.ply" "$scratch/noisy-horse.vtp" <<'PY'
import sys
import numpy as np
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.util.numpy_support import vtk_to_numpy
reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])
reader.Update()
horse = reader.GetOutput()
points = vtk_to_numpy(horse.GetPoints().GetData())
points += np.random.default_rng(7).normal(0.0, 0.001 * horse.GetLength(), points.shape)
horse.GetPoints().Modified()
writer = vtkXMLPolyDataWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputData(horse)
writer.Write()
PY
"$cli" "$scratch/noisy-horse.vtp" --medial-mesh "$scratch/m.vtp" --render "$out/prune-3d-before.png" --quiet
"$cli" "$scratch/noisy-horse.vtp" --prune --medial-mesh "$scratch/m.vtp" --render "$out/prune-3d-after.png" --quiet
"$cli" "$scratch/noisy-horse.vtp" --denoise --prune --medial-mesh "$scratch/m.vtp" --render "$out/prune-3d-denoised.png" --quiet
echo "wrote $out/prune-2d-before.png prune-2d-after.png prune-3d-before.png prune-3d-after.png prune-3d-denoised.png"
