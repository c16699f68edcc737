#!/usr/bin/env bash
# Runs every fracterra test: installs what it needs, builds, and runs ctest
# (native GoogleTest suites, Python ctypes tests, real Blender and POV-Ray),
# then the C ABI suites, fuzz replays and a few native programs again under
# ASan + UBSan (tests/sanitize.sh).
# Time (2 cores): the CI's clean-clone run took 1759 s (2026-11-26), then an
# estimated 28-32 min with the tests added since; "well under 25" is the aim.
# Measured 2026-11-27 on this machine, clean and idle: the sanitizer stage
# (with the subset below) took 577 s (546 s of it the build, 258 s of that the CLI's 30 files under
# UBSan + ASan), and the Release ctest 352 s. So: the sanitizer build leaves
# the CLI's own code uninstrumented and builds only the C ABI suites, the
# fuzz replays and three unit programs (tests/sanitize.sh); both builds are
# unity builds; the longest tests carry a ctest COST so that they start
# first. Each stage prints its start, so a CI log shows where time goes.
# The Windows stage (cross build of the library, CLI and C ABI suites; its
# tests run in the ctest stage under Wine, 39 s): about 9 minutes of CPU with
# the mingw dependencies cached in ~/.cache (about 4.5 min on 2 idle cores),
# 10 more to build those the first time (docs/windows.md). With it the run is
# over the 25-minute aim; FT_WINDOWS=0 leaves it out.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { echo "== tests/run.sh: $1 at $((SECONDS - start)) s"; }
stage "install"
scripts/install-deps.sh test
# Before the Linux build: its add-on zip then carries fracterra.dll, and its
# ctest runs the Windows programs under Wine (tests/windows, docs/windows.md).
# FT_WINDOWS=0 leaves it out (its tests then skip, saying why).
if [ "${FT_WINDOWS:-1}" != 0 ]; then
  stage "Windows build (mingw-w64)"
  scripts/build-windows.sh
fi
stage "Release build"
scripts/build.sh -DCMAKE_UNITY_BUILD=ON
stage "ctest"
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
stage "sanitizers"
tests/sanitize.sh
stage "done"
