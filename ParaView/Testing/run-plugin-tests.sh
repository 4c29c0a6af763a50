#!/bin/sh
# The ParaView plugin's tests, run from the main test suite: brings the plugin build that
# scripts/paraview.sh set up in BUILD_PARAVIEW up to date with the sources (incremental)
# and runs its ctest (pvpython loads the plugin and runs every proxy; pvbatch on 1 and 2
# MPI ranks). Exits 125 (skipped) when there is no such build: CI does not download
# ParaView unless asked to (MEDIALAXIS_PARAVIEW=1 sh scripts/test.sh).
# Usage: sh run-plugin-tests.sh BUILD_PARAVIEW
set -eu
DIR=$1
if [ ! -f "$DIR/build/CTestTestfile.cmake" ] || [ ! -x "$DIR/root/usr/bin/pvpython" ]; then
  echo "skipped: no ParaView plugin build in $DIR (sh scripts/paraview.sh sets it up)"
  exit 125
fi
cmake --build "$DIR/build"
cd "$DIR/build"
ctest --output-on-failure --no-tests=error
