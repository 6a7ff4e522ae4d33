#!/usr/bin/env bash
# Installs the Debian packages PCL-TDA needs that are missing, and nothing else.
# Safe to run again: when everything is there it does nothing.
set -euo pipefail

packages=(
  cmake g++ make pkg-config          # build
  libpcl-dev libeigen3-dev libboost-dev # libraries
  libthrust-dev libcub-dev              # the gpu/ module's OpenMP backend
  libgtest-dev libbenchmark-dev ccache  # tests and build speed
  clang-format doxygen                  # format check and API reference
  clang                                 # libFuzzer targets (test/fuzz)
  ripser libphat-dev libgudhi-dev time # reference tools and timing, for tests and benchmarks
  libpng-dev                            # the tools' PNG pictures
  libx11-dev xvfb xauth                 # pcl_tda_viewer; its tests and the demo on a virtual display
  librsvg2-bin                          # rsvg-convert: the tools' -png, SVG pictures as PNG
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y "${missing[@]}"
