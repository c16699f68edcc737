#!/usr/bin/env bash
# Runs every fracterra test: installs what it needs, builds, and runs ctest
# (native GoogleTest suites, Python ctypes tests, real Blender and POV-Ray),
# then the native tests again under ASan + UBSan (tests/sanitize.sh).
# Time (2 cores): the clean-clone run took 1759 s (2026-11-26). Its parts, in
# CPU seconds per compile measured on the compile commands: a library source
# takes ~2 s in Release and ~3 s under ASan with -g, ~2.5 s with -g1 (5
# sources: 18.4 / 22.7 / 18.6 s); 8 of them as one unity source 7.7 s instead
# of 14.7 s; the 7 benchmarks 30 s in all (kept: 2% of the Release build).
# So sanitize.sh builds unity with -g1, and the longest tests carry a ctest
# COST so that they start first.
# The Release build is a unity build too (the terrain methods and the CLI
# stay one source each: native/CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { echo "== tests/run.sh: $1 at $((SECONDS - start)) s"; }
stage "install"
scripts/install-deps.sh test
stage "Release build"
scripts/build.sh -DCMAKE_UNITY_BUILD=ON
stage "ctest"
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
stage "sanitizers"
tests/sanitize.sh
stage "done"
