#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the native tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (clang, -O1, in ${FT_ASAN_BUILD_DIR:-build-asan}) and runs them: the C ABI
# suites, the unit tests named below, the CLI they drive and the fuzz corpus
# replays (ctest label "native"). Any sanitizer report fails the run. Benchmarks are not
# built, so this adds only the native tests' own build time to the CI.
# The same build holds the libFuzzer harnesses (FT_FUZZ=ON beside
# FT_SANITIZE=ON: the library is compiled once, with the fuzzer's coverage
# instrumentation, for the sanitizer tests and the fuzzing alike;
# tests/run.sh fuzzes with FT_FUZZ_BUILD_DIR=build-asan). Two builds of the
# library (gcc -O0 here, clang -O1 in build-fuzz) were ~470 + ~520 s of CPU.
# The build is the CI's longest step, so: a unity build (8 library sources per
# compile: the standard headers and their templates once, not 8 times) and
# -g1 (line tables only: the stack traces keep file:line; -g's full debug
# information cost ~25% more per compile, and more in every link), and -O1
# as the fuzzers want it (executions per second); the sanitizer tests run
# faster than at -O0 too. ASan checks every access that is left after -O1's
# optimisation (a load whose value is never used may go, as in any
# optimised build); clang's `undefined` includes float-cast-overflow.
# Usage: tests/sanitize.sh [build|test]: both by default; tests/run.sh builds
# while the Release ctest runs, then tests.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FT_ASAN_BUILD_DIR:-build-asan}
step=${1:-all}
case "$step" in all | build | test) ;; *) echo "usage: $0 [build|test]" >&2; exit 2 ;; esac
# Which unit-test programs: FT_ASAN_UNIT_TESTS="all" for every one (19
# minutes for the whole script on a loaded machine, 2026-11-26); by default the C ABI suites (always), the fuzz
# replays (always), and the programs below: bad input, the erosion watchdog
# and the raster readers, where memory errors would hide. The Release build
# runs every test without the sanitizers.
unit_tests=${FT_ASAN_UNIT_TESTS:-hardening_test;erosion_watchdog_test;raster_test}
if [ "$step" != test ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
    -DCMAKE_C_FLAGS_DEBUG="-g1 -O1" -DCMAKE_UNITY_BUILD=ON -DFT_SANITIZE=ON -DFT_FUZZ=ON -DFT_BUILD_BENCH=OFF \
    -DFT_SANITIZE_UNIT_TESTS="$unit_tests" >/dev/null
  cmake --build "$build" -j"$(nproc)"
fi
[ "$step" != build ] || exit 0
# Leaks are errors (detect_leaks); the first report stops the test with a
# stack trace. OpenMP (libgomp) needs no suppression: its thread pool is
# still reachable at exit, so LeakSanitizer does not count it.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:abort_on_error=1:print_stacktrace=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
cd "$build"
# Of the eroded-window cases (tests/native/eroded_window_capitest.cpp), the
# ones whose memory paths another case here takes too: "periodic land" is
# "periodic land with a sea and a mask" without the sea and the mask, "land"
# cuts the same sixteen windows of a bounded square as "fbm badlands" does of
# a bounded oblong, and the five presets' own code runs here in every
# preset's erosion watchdog test; and "TilesAreTheWholesSamples" cuts
# "periodic land" into tiles of 256, windows on the same torus. They were
# 384 s of these tests' 710 s (2026-12-04, idle machine); the Release ctest
# runs every case. (ctest's names end in "  # GetParam() = N".)
asan_skip=${FT_ASAN_SKIP-'^ErodedWindow(/ErodedWindowOfCase\.SixteenOddWindowsAreTheWholesSamples/(land|periodic_land|valleys|rain|scree|badlands)( |$)|\.TilesAreTheWholesSamples$)'}
ctest -L native ${asan_skip:+-E "$asan_skip"} --output-on-failure -j"$(nproc)" --timeout "${FT_ASAN_TIMEOUT:-600}"
