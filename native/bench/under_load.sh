#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Erosion on 1 and 2 threads, idle and under a fixed background load of one
# busy-loop process per core (started and killed here): medians of ROUNDS
# wall times of `fracterra erode --preset land` on an fBm terrain of SIZE^2.
# Issue 25: under load two OpenMP threads lost to one (each barrier
# spin-waits for a thread the kernel descheduled). The library now takes no
# more threads than the cores other processes leave free;
# FT_THREADS_IGNORE_LOAD=1 shows what 2 threads did before ("2, load ignored").
# Usage: native/bench/under_load.sh [BUILD_DIR] [SIZE] [ROUNDS]   (defaults: build 513 3)
# Each row shows /proc/loadavg after it: the machine may carry other load too.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
size=${2:-513}
rounds=${3:-3}
cli="$(pwd)/$build/native/fracterra"
work=$(mktemp -d)
busy=()
stop_load() {
  if ((${#busy[@]})); then kill "${busy[@]}" 2>/dev/null || true; wait "${busy[@]}" 2>/dev/null || true; fi
  busy=()
}
trap 'stop_load; rm -rf "$work"' EXIT
"$cli" terrain --method fbm --size "$size" --seed 1 --out "$work/t.npy" >/dev/null

# One row: label, threads, then VAR=value settings for the runs.
row() {
  local label=$1 threads=$2; shift 2
  local times=() t0 t1
  for ((r = 0; r < rounds; ++r)); do
    t0=$(date +%s%N)
    env "$@" "$cli" erode --in "$work/t.npy" --preset land --threads "$threads" --out "$work/e.npy" >/dev/null
    t1=$(date +%s%N)
    times+=("$(((t1 - t0) / 1000000))")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk -v n="$rounds" -v phase="$phase" -v label="$label" \
    -v load="$(cut -d' ' -f1-4 /proc/loadavg)" \
    '{a[NR] = $1 / 1000} END {s = sprintf("%.2f", a[1]); for (i = 2; i <= n; ++i) s = s sprintf(" / %.2f", a[i]);
      printf "%-7s %-18s %8.2f   %-24s %s\n", phase, label, a[int((n + 1) / 2)], s, load}'
}

printf '%-7s %-18s %8s   %-24s %s\n' phase threads median "rounds (s, sorted)" "/proc/loadavg"
for phase in idle loaded; do
  if [ "$phase" = loaded ]; then
    for ((c = 0; c < $(nproc); ++c)); do
      (exec bash -c 'while :; do :; done') &
      busy+=($!)
    done
    sleep 3  # the busy loops are running
  fi
  row "1" 1
  row "2" 2
  row "2, load ignored" 2 FT_THREADS_IGNORE_LOAD=1
done
