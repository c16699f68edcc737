#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configures and builds fracterra (Release) into ${FT_BUILD_DIR:-build}.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FT_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
