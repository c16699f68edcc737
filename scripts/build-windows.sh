#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Cross-compiles fracterra for Windows x64 with Debian's mingw-w64 into
# ${FT_WINDOWS_BUILD_DIR:-build-windows}: bin/fracterra.dll, bin/fracterra.exe
# and the C ABI test program, all linked statically against the C++ runtime,
# libgomp and winpthreads (they need only DLLs Windows ships). Installs what
# it needs (scripts/install-deps.sh windows), builds the dependencies once
# (scripts/mingw-deps.sh, cached outside the repository), then the project.
# The tests run under Wine from the Linux build's ctest (tests/windows/).
# See docs/windows.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FT_WINDOWS_BUILD_DIR:-build-windows}
scripts/install-deps.sh windows
prefix=$(scripts/mingw-deps.sh | tail -n 1)
# The header-only libraries, from the build machine's Debian packages (the
# versions the Linux build uses), copied so that the cross compiler never
# sees /usr/include.
headers=$build/header-only
rm -rf "$headers"
mkdir -p "$headers/include"
cp -r /usr/include/nlohmann /usr/include/Random123 /usr/include/CLI /usr/include/tiny_obj_loader.h "$headers/include/"
FT_MINGW_PREFIX=$prefix cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/mingw-w64-x86_64.cmake" -DFT_MINGW_PREFIX="$prefix;$PWD/$headers" \
  -DCMAKE_RUNTIME_OUTPUT_DIRECTORY="$PWD/$build/bin" -DCMAKE_UNITY_BUILD=ON \
  -DFT_BUILD_BENCH=OFF "$@" >/dev/null
cmake --build "$build" -j"$(nproc)" --target fracterra fracterra_cli windows_capitests
