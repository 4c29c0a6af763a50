#!/bin/sh
# Installs, builds, and runs medial-axis on the built-in demo shape:
# writes medial.vtp (the medial balls) and medial.png (a picture).
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
xvfb-run -a build/bin/medial-axis -n 20000 -o medial.vtp --render medial.png --stats
echo "wrote $(pwd)/medial.vtp and $(pwd)/medial.png"
