#!/bin/sh
# Installs the build and test dependencies on Debian 12 (run as root or with sudo).
# chromium: the browser test of the web page (headless, offline). nodejs and npm bundle
# the page's viewer at build time; a machine that has Node.js and npm already (e.g. from
# NodeSource, whose nodejs holds npm) keeps them.
set -eu
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq \
  cmake ninja-build g++ make libvtk9-dev python3-vtk9 vtk9 python3-numpy \
  libboost-dev libcgal-dev libeigen3-dev xvfb xauth libgl1-mesa-dri openmpi-bin libopenmpi-dev chromium doxygen >/dev/null
if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  $SUDO apt-get install -y -qq nodejs npm >/dev/null
fi
