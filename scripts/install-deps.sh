#!/bin/sh
# Installs the build and test dependencies on Debian 12 (run as root or with sudo).
set -eu
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq \
  cmake ninja-build g++ make libvtk9-dev python3-vtk9 vtk9 python3-numpy \
  libboost-dev libcgal-dev libeigen3-dev xvfb xauth libgl1-mesa-dri openmpi-bin libopenmpi-dev >/dev/null
