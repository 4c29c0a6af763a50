#!/bin/sh
# Builds the ParaView plugin (ParaView/) against Debian's ParaView 5.11 and its own VTK 9.2,
# in build-paraview/, without installing ParaView:
#   1. apt-get download paraview paraview-dev python3-paraview, dpkg -x into build-paraview/root
#      (apt-get install paraview would remove python3-vtk9 and libvtk9-dev: never do that);
#   2. installs what pvpython, pvbatch and the build need beside them (MPI, ParaView's
#      runtime libraries; with --gui also the GUI's Qt libraries);
#   3. configures ParaView/ in build-paraview/build and builds MedialAxis.so;
#   4. with --test, runs its tests: pvpython loads the plugin and runs every proxy, and
#      pvbatch on 1 and 2 MPI ranks gives the same balls and reconstruction.
# Usage: sh scripts/paraview.sh [--test] [--gui]     (run as root, or with sudo for apt)
# Afterwards: build-paraview/root/usr/bin/{pvpython,pvbatch,paraview}, with
#   LD_LIBRARY_PATH=build-paraview/root/usr/lib/x86_64-linux-gnu, and the plugin
#   build-paraview/build/lib/paraview-5.11/plugins/MedialAxis/MedialAxis.so (see docs/paraview.md).
set -eu
cd "$(dirname "$0")/.."
TEST=0
GUI=0
for arg in "$@"; do
  case "$arg" in
    --test) TEST=1 ;;
    --gui) GUI=1 ;;
    *) echo "usage: sh scripts/paraview.sh [--test] [--gui]" >&2; exit 2 ;;
  esac
done
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
APT="$SUDO apt-get -o DPkg::Lock::Timeout=600"
DIR=$(pwd)/build-paraview
ROOT="$DIR/root"
ARCH=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
mkdir -p "$DIR/debs"

# 1. Download and unpack (once).
if [ ! -x "$ROOT/usr/bin/pvpython" ]; then
  (cd "$DIR/debs" && { apt-get download -qq paraview paraview-dev python3-paraview 2>/dev/null ||
    { $APT update -qq && apt-get download -qq paraview paraview-dev python3-paraview; }; })
  for deb in "$DIR"/debs/*.deb; do dpkg -x "$deb" "$ROOT"; done
fi

# 2. What the unpacked programs and the build use from the system: ParaView's own runtime
# dependencies (most come with libvtk9-dev already), MPI's launcher and headers. tclsh, the
# Python modules of ParaView's web server and plots (autobahn, twisted, matplotlib), and
# Qt's help and OpenGL modules (GUI only) are left out unless --gui.
deps=$(dpkg-deb -f "$DIR"/debs/paraview_*.deb Depends | tr ',' '\n' | sed -e 's/([^)]*)//g' -e 's/|.*//' -e 's/ //g' |
  grep -v -e '^$' -e '^python3-matplotlib' -e '^python3-autobahn' -e '^python3-twisted' \
    -e '^libqt5help5' -e '^libqt5opengl5' -e '^tclsh')
[ "$GUI" -eq 1 ] && deps="$deps libqt5help5 libqt5opengl5 python3-matplotlib"
missing=""
for p in $deps openmpi-bin libopenmpi-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "paraview.sh: installing$missing"
  # shellcheck disable=SC2086
  $APT install -y -qq --no-install-recommends $missing >/dev/null
fi

# 3. Configure and build the plugin.
cmake -S ParaView -B "$DIR/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="$ROOT/usr/lib/$ARCH/cmake/paraview-5.11" -DPython3_EXECUTABLE=/usr/bin/python3 -DBUILD_TESTING=ON \
  -Wno-dev >"$DIR/configure.log" || { tail -30 "$DIR/configure.log"; exit 1; }
cmake --build "$DIR/build"
echo "paraview.sh: plugin $DIR/build/lib/paraview-5.11/plugins/MedialAxis/MedialAxis.so"

# 4. Tests (pvbatch under mpiexec; no display needed).
if [ "$TEST" -eq 1 ]; then
  cd "$DIR/build"
  ctest --output-on-failure --no-tests=error
fi
