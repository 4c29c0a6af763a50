#!/bin/sh
# Checks once that medialaxis renders offscreen without X (not part of CI: it compiles VTK).
#
# Builds a minimal VTK 9.1 from Debian's own source package with OSMesa and without X
# (VTK_OPENGL_HAS_OSMESA=ON, VTK_USE_X=OFF, only the VTK modules the top-level
# CMakeLists.txt asks for), builds the project against it, and runs the image tests
# with DISPLAY unset.
#
#   nice -n 19 sh scripts/vtk-osmesa.sh [WORKDIR]      (default WORKDIR: build-osmesa/)
#
# Debian's source package has most bundled third-party libraries removed, so VTK uses
# the system ones, except GLEW: Debian's libGLEW resolves GL functions through GLX,
# which finds nothing under an OSMesa context. Debian's glew source is compiled once
# more with GLEW_OSMESA (functions through OSMesaGetProcAddress) as a static library.
# Run as root or with sudo (apt). Rerunning reuses what is already built.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=$(mkdir -p "${1:-$ROOT/build-osmesa}" && cd "${1:-$ROOT/build-osmesa}" && pwd)
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
APT="$SUDO apt-get -o DPkg::Lock::Timeout=900"
stamp() { echo "[vtk-osmesa $(date +%T)] $*"; }
START=$(date +%s)

# 1. Source packages: one deb-src line for bookworm, then apt-get source vtk9 and glew.
if ! grep -rqs "deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  stamp "adding a deb-src line for bookworm"
  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm bookworm-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
    $SUDO tee /etc/apt/sources.list.d/bookworm-src.sources >/dev/null
fi
$APT update -qq
$APT install -y -qq dpkg-dev cmake ninja-build g++ libosmesa6-dev libboost-dev \
  libfreetype-dev libpng-dev libjpeg-dev libtiff-dev zlib1g-dev libexpat1-dev liblz4-dev \
  liblzma-dev libdouble-conversion-dev libutfcpp-dev libeigen3-dev libjsoncpp-dev >/dev/null
mkdir -p "$WORK/src"
cd "$WORK/src"
ls -d vtk9-9.1.0*/ >/dev/null 2>&1 || apt-get source -qq vtk9 >/dev/null
ls -d glew-2.* >/dev/null 2>&1 || apt-get source -qq glew >/dev/null
VTK_SRC=$(ls -d "$WORK"/src/vtk9-9.1.0*/ | head -1)
GLEW_SRC=$(ls -d "$WORK"/src/glew-2.*/ | head -1)

# 2. GLEW for OSMesa (static, position-independent).
if [ ! -f "$WORK/glew-osmesa/lib/libGLEW.a" ]; then
  stamp "building GLEW with GLEW_OSMESA"
  make -s -C "$GLEW_SRC" SYSTEM=linux-osmesa glew.lib.static >"$WORK/glew-build.log" 2>&1
  mkdir -p "$WORK/glew-osmesa/lib" "$WORK/glew-osmesa/include/GL"
  cp "$GLEW_SRC"/lib/libGLEW.a "$WORK/glew-osmesa/lib/"
  cp "$GLEW_SRC"/include/GL/*.h "$WORK/glew-osmesa/include/GL/"
fi

# 3. VTK: only the modules find_package(VTK ... COMPONENTS ...) names in CMakeLists.txt.
COMPONENTS=$(sed -n '/^find_package(VTK /,/)/p' "$ROOT/CMakeLists.txt" |
  sed -e 's/find_package(VTK [0-9.]* REQUIRED COMPONENTS//' -e 's/)//' | tr -s ' \n' '  ')
ENABLE=""
for c in $COMPONENTS; do ENABLE="$ENABLE -DVTK_MODULE_ENABLE_VTK_$c=YES"; done
EXTERNAL=""
for t in doubleconversion eigen expat freetype glew jpeg jsoncpp lz4 lzma png tiff utf8 zlib; do
  EXTERNAL="$EXTERNAL -DVTK_MODULE_USE_EXTERNAL_VTK_$t=ON"
done
stamp "configuring VTK with: $COMPONENTS"
# shellcheck disable=SC2086
cmake -S "$VTK_SRC" -B "$WORK/vtk" -G Ninja -Wno-dev \
  -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON \
  -DVTK_BUILD_TESTING=OFF -DVTK_BUILD_EXAMPLES=OFF -DVTK_BUILD_DOCUMENTATION=OFF \
  -DVTK_WRAP_PYTHON=OFF -DVTK_WRAP_JAVA=OFF -DVTK_ENABLE_WRAPPING=OFF \
  -DVTK_BUILD_ALL_MODULES=OFF \
  -DVTK_GROUP_ENABLE_Imaging=DONT_WANT -DVTK_GROUP_ENABLE_MPI=DONT_WANT \
  -DVTK_GROUP_ENABLE_Qt=NO -DVTK_GROUP_ENABLE_Rendering=DONT_WANT \
  -DVTK_GROUP_ENABLE_StandAlone=DONT_WANT -DVTK_GROUP_ENABLE_Views=DONT_WANT \
  -DVTK_GROUP_ENABLE_Web=DONT_WANT \
  -DVTK_OPENGL_HAS_OSMESA=ON -DVTK_USE_X=OFF -DVTK_DEFAULT_RENDER_WINDOW_OFFSCREEN=ON \
  -DVTK_SMP_IMPLEMENTATION_TYPE=STDThread \
  -DGLEW_INCLUDE_DIR="$WORK/glew-osmesa/include" -DGLEW_LIBRARY="$WORK/glew-osmesa/lib/libGLEW.a" \
  $ENABLE $EXTERNAL >"$WORK/vtk-configure.log"
stamp "building VTK ($(grep -c '^build.*\.o:' "$WORK/vtk/build.ninja" || true) objects)"
T0=$(date +%s)
cmake --build "$WORK/vtk" >"$WORK/vtk-build.log"
T1=$(date +%s)
stamp "VTK built in $((T1 - T0)) s"

# 4. The project against it (no Python: the image tests are C++ and the CLI).
cmake -S "$ROOT" -B "$WORK/project" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DVTK_DIR="$WORK/vtk/lib/cmake/vtk-9.1" -DMEDIALAXIS_WRAP_PYTHON=OFF >"$WORK/project-configure.log"
cmake --build "$WORK/project" >"$WORK/project-build.log"
T2=$(date +%s)
stamp "project built in $((T2 - T1)) s"

# 5. The image tests (every test that renders), with no X display at all.
cd "$WORK/project"
grep -q "^#define VTK_USE_X" "$WORK/vtk/Rendering/OpenGL2/vtkRenderingOpenGLConfigure.h" &&
  { echo "VTK was built with X: not an OSMesa build" >&2; exit 1; }
stamp "image tests with DISPLAY unset"
status=0
env -u DISPLAY -u WAYLAND_DISPLAY ctest --output-on-failure -R 'Render|render|png|pipeline' || status=$?
stamp "done in $(($(date +%s) - START)) s (VTK $((T1 - T0)) s, project $((T2 - T1)) s)"
exit $status
