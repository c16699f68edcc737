#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer harnesses (clang, ASan + UBSan, FT_FUZZ=ON) in
# build-fuzz/ and runs each for SECONDS, one after the other (or all at once
# under `nice -n 19` with FT_FUZZ_PARALLEL=1, so a long run of every harness
# fits in the wall time of one), printing the executions each survived. New interesting inputs collect in
# build-fuzz/fuzz-work/<harness>/ (not committed); a crash is saved under
# build-fuzz/fuzz-artifacts/<harness>/: copy it to
# tests/fuzz/regressions/<harness>/ once fixed, and ctest replays it forever.
# SECONDS 0 only builds them (tests/run.sh builds them beside ctest, then
# runs each for 20 s).
# Usage: [FT_FUZZ_PARALLEL=1 [FT_FUZZ_JOBS=N]] tests/fuzz/run_fuzzers.sh SECONDS [harness ...]   (default: all)
set -euo pipefail
cd "$(dirname "$0")/../.."
secs=${1:?usage: tests/fuzz/run_fuzzers.sh SECONDS [harness ...]}
shift
build=${FT_FUZZ_BUILD_DIR:-build-fuzz}
if (($#)); then
  harnesses=("$@")
else
  harnesses=()
  for f in tests/fuzz/fuzz_*.cpp; do h=$(basename "$f" .cpp); harnesses+=("${h#fuzz_}"); done
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_UNITY_BUILD=ON -DFT_FUZZ=ON -DFT_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build" -j"${FT_FUZZ_BUILD_JOBS:-2}" --target "${harnesses[@]/#/fuzz_}" >/dev/null
((secs > 0)) || exit 0

# Leaks count as failures.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:print_stacktrace=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
# Idle OpenMP workers sleep instead of spinning: the fuzzer calls many small
# parallel regions on a machine that is shared.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}

# One harness; its exit status is the fuzzer's.
fuzz_one() {
  local h=$1 work="$build/fuzz-work/$1" art="$build/fuzz-artifacts/$1/" log="$build/fuzz-logs/$1.log"
  mkdir -p "$work" "$art" "$(dirname "$log")"
  local dirs=("$work" "tests/fuzz/corpus/$h")
  [ -d "tests/fuzz/regressions/$h" ] && dirs+=("tests/fuzz/regressions/$h")
  $nice "$build/tests/fuzz_$h" -max_total_time="$secs" -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$art" "${dirs[@]}" >"$log" 2>&1
}

report() {
  local h=$1 rc=$2 log="$build/fuzz-logs/$1.log" result=ok
  ((rc == 0)) || { result="FAILED (see $log, $build/fuzz-artifacts/$h/)"; failed=1; }
  execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log" | tail -1)
  printf '%-18s %8s %12s  %s\n' "$h" "$secs" "${execs:-?}" "$result"
}

failed=0
nice=
# libFuzzer's timeout is wall time: under `nice -n 19` on a loaded shared
# machine an input of 1.6 s of CPU took 14 s, so parallel runs allow 60 s.
timeout=${FT_FUZZ_TIMEOUT:-10}
[ "${FT_FUZZ_PARALLEL:-0}" = 1 ] && timeout=${FT_FUZZ_TIMEOUT:-60}
printf '%-18s %8s %12s  %s\n' harness seconds executions result
if [ "${FT_FUZZ_PARALLEL:-0}" = 1 ]; then
  nice="nice -n 19"
  # FT_FUZZ_JOBS=N: at most N at once (the long runs: two at a time, each
  # with a core of its own on 2 cores), reported as each ends.
  jobs=${FT_FUZZ_JOBS:-${#harnesses[@]}}
  declare -A names
  running=0
  for h in "${harnesses[@]}"; do
    if ((running >= jobs)); then
      rc=0; wait -n -p done_pid || rc=$?; report "${names[$done_pid]}" "$rc"; running=$((running - 1))
    fi
    fuzz_one "$h" & names[$!]=$h; running=$((running + 1))
  done
  while ((running > 0)); do
    rc=0; wait -n -p done_pid || rc=$?; report "${names[$done_pid]}" "$rc"; running=$((running - 1))
  done
else
  for h in "${harnesses[@]}"; do rc=0; fuzz_one "$h" || rc=$?; report "$h" "$rc"; done
fi
exit $failed
