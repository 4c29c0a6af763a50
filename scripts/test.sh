#!/bin/sh
# Installs, builds, and runs the whole test suite under Xvfb; then builds the ParaView
# plugin against Debian's ParaView (unpacked in build-paraview/, not installed) and runs
# its pvpython and pvbatch (1 and 2 MPI ranks) tests.
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
(cd build && xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j2)
sh scripts/paraview.sh --test
