#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every fracterra test: installs what it needs, builds, and runs ctest
# (native GoogleTest suites, Python ctypes tests, real Blender and POV-Ray),
# then the C ABI suites, fuzz replays and a few native programs again under
# ASan + UBSan (tests/sanitize.sh).
# Time (2 cores): the CI's fresh-clone runs took 1804 s and more (2026-12-02,
# the stages one after the other: Windows 870 s from a cold mingw cache,
# Release build 506 s, ctest 899 s). Since then the stages that use different
# resources overlap: the Windows build beside the Release build, the
# sanitizer tree (clang, also the fuzzers' build) and its tests beside
# everything at nice 19, the Blender 4.3 root and the Wine prefix made beside
# the builds. docs/measurements/ci.md has the stage times and the slowest
# tests. "Well under 25 minutes" is the aim, on a fresh machine too.
# Each stage prints its start, so a CI log shows where time goes.
# FT_WINDOWS=0 leaves the Windows stage out, FT_FUZZ=0 the fuzzing.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
# OpenMP's idle threads sleep rather than spin while two tests share the two
# cores (tests/CMakeLists.txt, FT_TEST_OMP, measures it); here for the
# Python and Blender tests too.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
stage() { echo "== tests/run.sh: $1 at $((SECONDS - start)) s"; }
windows=${FT_WINDOWS:-1}
# FT_FUZZ=0 leaves the fuzz stage out.
fuzz=${FT_FUZZ:-1}
stage "install"
scripts/install-deps.sh test
# Both package sets before anything runs beside another: one apt at a time.
[ "$windows" = 0 ] || scripts/install-deps.sh windows
mkdir -p build
asan_log=$PWD/build/sanitizer-build.log
fuzz_log=$PWD/build/fuzz-run.log
windows_log=$PWD/build/windows-build.log
asan_built=$PWD/build/sanitizer-build.done
ended=$PWD/build/background-builds.ended
rm -f "$asan_built" "$ended"
# The sanitizer build (clang, ASan + UBSan, with the libFuzzer harnesses in
# the same tree: tests/sanitize.sh), then its tests, run from the start at
# the lowest priority, so they take a core only while the other stages leave
# one idle (the Windows stage's downloads and configure scripts, Blender
# waiting on its window, the last long tests finishing alone). Their wall
# time then depends on the other stages: the per-test timeout is 25 minutes
# (a hang, not a busy machine).
asan_test_log=$PWD/build/sanitizer-tests.log
asan_passed=$PWD/build/sanitizer-tests.passed
rm -f "$asan_passed"
# Each stage beside another runs in its own process group, so that a failing
# stage stops them all.
background="" prefetch="" windows_build=""
stop_beside() {
  local group
  for group in "$background" "$prefetch" "$windows_build"; do
    [ -z "$group" ] || kill -- -"$group" 2>/dev/null || true
  done
}
trap stop_beside EXIT
# setsid gives a stage a session of its own, and with the kernel's autogroup
# scheduling (on in this machine's kernel: /proc/sys/kernel/sched_autogroup_enabled)
# each session is one group with an equal share of the CPU whatever its
# processes' nice values: so the session's own group gets the nice value too
# (/proc/self/autogroup), or "the lowest priority" would take a third of the
# cores from the Release build and ctest.
setsid --wait nice -n 19 bash -c 'echo 19 >/proc/self/autogroup 2>/dev/null || true
  trap "touch \"$3\"" EXIT
  tests/sanitize.sh build >"$1" 2>&1 || exit 1
  touch "$2"
  FT_ASAN_TIMEOUT=1500 tests/sanitize.sh test >"$4" 2>&1 || exit 1
  touch "$5"' _ "$asan_log" "$asan_built" "$ended" "$asan_test_log" "$asan_passed" &
background=$!
# What the tests would otherwise make on a fresh machine while a ctest slot
# waits, made now beside the builds, whose compiles leave the network and the
# disk idle: the Debian trixie root with Blender 4.3 (scripts/blender4-root.sh,
# about 3 minutes of downloads and dpkg the first time, nothing later) and
# the Wine prefix (about 10 s). Each keeps its own lock, so a test that comes
# first waits for it and reuses it; a failure here leaves the test to report.
prefetch_log=$PWD/build/prefetch.log
setsid --wait nice -n 10 bash -c 'echo 10 >/proc/self/autogroup 2>/dev/null || true
  scripts/blender4-root.sh >/dev/null || true
  [ "$1" = 0 ] || tests/windows/wine_run.sh --prepare || true' _ "$windows" >"$prefetch_log" 2>&1 &
prefetch=$!
# The Windows build beside the Release build: its mingw dependencies
# (scripts/mingw-deps.sh: source downloads, FFTW's serial configure scripts)
# leave a core idle much of the time, which the Release build takes. The
# Linux build's add-on zip and wheels carry its fracterra.dll, and its ctest
# runs the Windows programs under Wine (tests/windows, docs/windows.md): so
# the Release build leaves the packages out (-DFT_PACKAGES=OFF), and once
# both are done it runs again, configure finds the DLL, and only the packages
# are made. FT_WINDOWS=0 leaves it out (its
# tests then skip, saying why).
if [ "$windows" != 0 ]; then
  stage "Windows build (mingw-w64), beside the Release build; its log: $windows_log"
  setsid --wait scripts/build-windows.sh >"$windows_log" 2>&1 &
  windows_build=$!
fi
# No benchmarks (native/bench): no test runs them, and they were 30 s of the
# build's CPU (scripts/build.sh -DFT_BUILD_BENCH=ON brings them back).
stage "Release build"
# With the Windows build beside it, its packages wait for the DLL (below).
packages=ON
[ "$windows" = 0 ] || packages=OFF
scripts/build.sh -DCMAKE_UNITY_BUILD=ON -DFT_BUILD_BENCH=OFF -DFT_PACKAGES=$packages
if [ -n "$windows_build" ]; then
  stage "the rest of the Windows build"
  windows_rc=0
  wait "$windows_build" || windows_rc=$?
  windows_build=""
  cat "$windows_log"
  ((windows_rc == 0)) || { echo "tests/run.sh: the Windows build failed" >&2; exit 1; }
  stage "the packages, with fracterra.dll"
  scripts/build.sh -DCMAKE_UNITY_BUILD=ON -DFT_BUILD_BENCH=OFF -DFT_PACKAGES=ON
fi
stage "the Blender 4.3 root and the Wine prefix (made beside the builds)"
wait "$prefetch" || true
prefetch=""
cat "$prefetch_log"
stage "ctest (the sanitizer build and tests beside it, nice 19)"
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
stage "sanitizers (the rest of their build and tests; every harness fuzzing for ${FT_FUZZ_SECONDS:-20} s beside)"
while [ ! -e "$asan_built" ] && [ ! -e "$ended" ]; do sleep 1; done
if [ ! -e "$asan_built" ]; then
  cat "$asan_log"; echo "tests/run.sh: the sanitizer build failed" >&2; exit 1
fi
# Every harness fuzzes for 20 s, all at once at nice 19 (a new finding fails
# the run: its input is in build-asan/fuzz-artifacts/, tests/fuzz/run_fuzzers.sh
# says how to keep it as a regression).
(
  [ "$fuzz" != 0 ] || { echo "FT_FUZZ=0: no fuzzing"; exit 0; }
  # 120 s per input: at nice 19 beside the sanitizer tests, 13 harnesses share
  # 2 cores, and a slow EXR input (2.7 s of CPU under ASan) took 60 s of wall.
  FT_FUZZ_BUILD_DIR=build-asan FT_FUZZ_PARALLEL=1 FT_FUZZ_TIMEOUT=${FT_FUZZ_TIMEOUT:-120} \
    tests/fuzz/run_fuzzers.sh "${FT_FUZZ_SECONDS:-20}"
) >"$fuzz_log" 2>&1 &
fuzzing=$!
while [ ! -e "$ended" ]; do sleep 1; done
background=""
fuzz_rc=0
wait "$fuzzing" || fuzz_rc=$?
trap - EXIT
stage "sanitizer tests"
cat "$asan_test_log"
stage "fuzzing (every harness for ${FT_FUZZ_SECONDS:-20} s)"
cat "$fuzz_log"
[ -e "$asan_passed" ] || { echo "tests/run.sh: the sanitizer tests failed" >&2; exit 1; }
((fuzz_rc == 0)) || { echo "tests/run.sh: fuzzing failed (a finding, or the fuzz build)" >&2; exit 1; }
stage "done"
