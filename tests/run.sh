#!/usr/bin/env bash
# Runs every fracterra test: installs what it needs, builds, and runs ctest
# (native GoogleTest suites, Python ctypes tests, real Blender and POV-Ray),
# then the native tests again under ASan + UBSan (tests/sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
tests/sanitize.sh
