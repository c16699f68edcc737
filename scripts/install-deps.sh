#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian packages fracterra needs to build, test and run its
# demo. Packages already present are skipped, so a second run costs nothing.
# Usage: scripts/install-deps.sh [build|test|demo|windows]   (default: test, the
# superset of the first three; windows: the cross build and Wine, docs/windows.md)
set -euo pipefail

build_pkgs=(cmake make g++ pkg-config libpng-dev libfftw3-dev librandom123-dev libcli11-dev
            nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libosd-dev
            libtinyobjloader-dev libnoise-dev libgdal-dev libopenexr-dev
            python3-setuptools python3-wheel python3-venv)  # the Python wheel (python/CMakeLists.txt)
run_pkgs=(povray povray-includes blender python3 python3-numpy librsvg2-bin
          python3-distributed python3-dask python3-tqdm)  # the Dask tile driver (docs/scale.md)
test_pkgs=(python3-pytest python3-matplotlib clang libclang-rt-14-dev libomp-dev xvfb xauth xdotool debootstrap gdal-bin
           python3-gdal grass-core)  # grass-core: tests/grass, the drainage map against r.terraflow (installs in ~15 s)

# The Windows cross build (scripts/build-windows.sh) and its tests under Wine;
# dpkg-dev unpacks the Debian source packages of libpng and FFTW; googletest is
# the GoogleTest source built for mingw.
windows_pkgs=(cmake make g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64
              libz-mingw-w64-dev wine64 dpkg-dev googletest nlohmann-json3-dev librandom123-dev libcli11-dev libtinyobjloader-dev
              python3)

case "${1:-test}" in
  build) want=("${build_pkgs[@]}") ;;
  demo) want=("${build_pkgs[@]}" "${run_pkgs[@]}") ;;
  test) want=("${build_pkgs[@]}" "${run_pkgs[@]}" "${test_pkgs[@]}") ;;
  windows) want=("${windows_pkgs[@]}") ;;
  *) echo "usage: $0 [build|test|demo|windows]" >&2; exit 2 ;;
esac

# One dpkg-query for the whole list (one per package took ~15 s at load).
# It exits 1 when a package is unknown to dpkg (never installed, as on a
# fresh machine): that is an answer here, not a failure.
installed=" $( (dpkg-query -W -f='${Package} ${Status}\n' "${want[@]}" 2>/dev/null || true) |
              awk '/ install ok installed$/ {printf "%s ", $1}') "
missing=()
for p in "${want[@]}"; do
  [[ "$installed" == *" $p "* ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
