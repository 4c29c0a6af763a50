#!/bin/sh
# The web page's figures (docs/web-page.md): medial-axis --html for the demo shape (every
# layer), the horse with its medial mesh, a 2D shape (a triangulated L) and 300,000 of the
# horse's balls (the page keeps 100,000); each page's size in bytes and its load time in
# headless Chromium (open-page.js: from navigation to the first frame drawn; the median of
# three loads, each in a new browser). The page's picture, docs/images/web-page.png, is
# scripts/gallery.py's.
#   sh scripts/web-page-figures.sh [BUILD] [OUT]   (defaults: build, /tmp/medialaxis-web)
set -eu
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
out=${2:-/tmp/medialaxis-web}
mkdir -p "$out"
cli="$build/bin/medial-axis"
modules="$build/Rendering/Web/viewer/node_modules"
open_page="Rendering/Web/Testing/Browser/open-page.js"
horse=../shared/data/meshes/horse.ply
PYTHONPATH="$build/lib/python3/dist-packages" /usr/bin/python3 -c "
import sys, medialaxis
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
shape = medialaxis.vtkMedialShapeSource(); shape.SetShapeToLShape()
cut = vtkTriangleFilter(); cut.SetInputConnection(shape.GetOutputPort())
writer = vtkXMLPolyDataWriter(); writer.SetInputConnection(cut.GetOutputPort())
writer.SetFileName(sys.argv[1]); writer.Write()" "$out/l-shape-triangles.vtp"
"$cli" -n 10000 --threads 2 --medial-mesh "$out/jack-mesh.vtp" --thickness "$out/jack-thickness.vtp" \
  --reconstruct "$out/jack-union.vtp" --html "$out/jack.html" --quiet
"$cli" "$horse" --threads 2 --medial-mesh "$out/horse-mesh.vtp" --html "$out/horse.html" --quiet
"$cli" "$out/l-shape-triangles.vtp" -n 1000 --threads 2 --html "$out/l-shape.html" --quiet
"$cli" "$horse" -n 300000 --threads 2 --html "$out/horse-300k.html" --quiet
echo "| page | what it shows | bytes | load (ms, median of 3) |"
echo "|---|---|---:|---:|"
for page in jack horse l-shape horse-300k; do
  case $page in
    jack) what="demo:jack -n 10000: surface with thickness, balls, medial mesh, reconstruction" ;;
    horse) what="horse.ply (96,966 triangles): balls and medial mesh" ;;
    l-shape) what="triangulated L-shape -n 1000: outline, disks, 2D graph" ;;
    horse-300k) what="horse.ply -n 300000: balls, thinned to 100,000 on the page" ;;
  esac
  # Three loads, each in a new browser: the median.
  for run in 1 2 3; do
    node "$open_page" "$modules" /usr/bin/chromium "$out/$page.html" "$out/$page.png" --plain > "$out/$page-$run.json"
  done
  /usr/bin/python3 -c "
import json, statistics, sys
runs = [json.load(open(f'{sys.argv[1]}-{k}.json')) for k in (1, 2, 3)]
for r in runs:
    assert r['status'] == 'ready' and not r['consoleErrors'], r
load = statistics.median(r['loadMs'] for r in runs)
print(f\"| {sys.argv[2]} | {sys.argv[3]} | {runs[0]['bytes']:,} | {load:,.0f} |\")" "$out/$page" "$page.html" "$what"
done
