#!/bin/sh
# Installs, builds, and runs the whole test suite under Xvfb, the ParaView plugin's
# tests included: downloads Debian's ParaView (unpacked in build-paraview/, not
# installed) and builds the plugin against it (scripts/paraview.sh), so that the
# suite's paraview-plugin-tests runs the plugin's pvpython and pvbatch (1 and 2 MPI
# ranks) tests. MEDIALAXIS_PARAVIEW=0 leaves the plugin out (that test is then skipped
# unless build-paraview/ exists already).
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
if [ "${MEDIALAXIS_PARAVIEW:-1}" = 1 ]; then
  sh scripts/paraview.sh
fi
(cd build && xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j2)
