#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the benchmarks behind the README's speed table one after another, in
# one run, each with its baseline, and logs the load average before and after
# each: the source of the table's figures (medians of 3 repetitions, or 5 for
# the window overhead). Takes 15-20 minutes on the 2-core machine; run it on
# an otherwise idle machine.
#
#   native/bench/readme_figures.sh [BUILD_DIR] [OUT_DIR] [SECTION ...]
#
# SECTIONS: terrain window noise polyline povray subdiv blender erosion
# fluvial fastscapelib land memory (default: all; memory is not in the README's table), and eroded_tiles
# (only when named). Each writes OUT_DIR/SECTION.txt.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "${1:-build}")
out=$(realpath -m "${2:-/tmp/fracterra-figures}")
shift $(( $# > 2 ? 2 : $# ))
sections=("$@")
[ ${#sections[@]} -gt 0 ] || sections=(terrain window noise polyline povray subdiv blender erosion fluvial fastscapelib land)
mkdir -p "$out" "$out/ant"
gb=(--benchmark_repetitions=3 --benchmark_report_aggregates_only=true)

run() {  # SECTION COMMAND...: the command's output and the load around it
  local name=$1
  shift
  {
    echo "# $(date -u +%FT%TZ) $*"
    echo "# before: $(uptime)"
    "$@"
    echo "# after: $(uptime)"
  } >>"$out/$name.txt" 2>&1
  echo "$name: $out/$name.txt"
}

for s in "${sections[@]}"; do
  case $s in
    terrain) run terrain "$build/native/terrain_bench" "${gb[@]}" --benchmark_filter='Naive|FracterraMidpoint' ;;
    window)
      run window "$build/native/terrain_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_filter='MidpointWindow/threads:1|FracterraMidpoint/levels:12/threads:1' ;;
    noise)
      # fbm against FastNoise2 (issue 40; its rows need -DFT_FASTNOISE2_DIR) in
      # alternating rounds, medians of 7; passive OpenMP waits, so that a
      # 2-thread run's spinning worker does not bill the next run, and every
      # asked-for thread however loaded the machine (FT_THREADS_IGNORE_LOAD).
      OMP_WAIT_POLICY=passive FT_THREADS_IGNORE_LOAD=1 run noise "$build/native/noise_bench" \
        --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true \
        --benchmark_report_aggregates_only=true --benchmark_filter='Fracterra|FastNoise2'
      run noise "$build/native/noise_bench" "${gb[@]}" --benchmark_filter='Libnoise|Spectral' ;;
    polyline) run polyline "$build/native/polyline_bench" "${gb[@]}" ;;
    povray) run povray "$build/native/povray_bench" --repetitions 3 ;;
    subdiv) (cd "$build/native" && run subdiv ./subdiv_bench "${gb[@]}") ;;
    blender)
      run blender blender -b --factory-startup --python examples/bench_blender.py -- --repeat 3 \
        --library "$build/native/libfracterra.so" ;;
    erosion)
      run erosion blender -b --factory-startup --python native/bench/ant_eroder_anchor.py -- "$out/ant" 513 1025
      for t in 1 2; do
        FT_ANT_DIR="$out/ant" FT_BENCH_THREADS=$t run erosion "$build/native/erosion_bench" "${gb[@]}" \
          --benchmark_filter=AntPasses
      done ;;
    fluvial) FT_STEPS=100 run fluvial "$build/native/erosion_bench" "${gb[@]}" --benchmark_filter=Fluvial/2049 ;;
    fastscapelib)
      # The fluvial step against fastscapelib v0.2.2's (issue 40; needs
      # -DFT_FASTSCAPELIB_DIR, else only fracterra's rows run): 10 steps on
      # 1025^2 and 2049^2, interleaved, ours on 2 threads and on 1 (fastscapelib
      # has one).
      for t in 2 1; do
        FT_STEPS=10 FT_BENCH_THREADS=$t run fastscapelib "$build/native/erosion_bench" "${gb[@]}" \
          --benchmark_enable_random_interleaving=true --benchmark_filter='^(Fluvial|Fastscapelib)/(1025|2049)/'
      done ;;
    land)
      # Issue 24's targets: `erode --preset land` (the landscape model, all
      # maps off) on 2 threads at 513^2, 1025^2 and 2049^2, three runs each
      # (the erosion's own seconds from --stats), against one A.N.T.
      # mesh.eroder(Iterations=1) on 1025^2 in the same run.
      run land blender -b --factory-startup --python native/bench/ant_eroder_anchor.py -- "$out/ant" 1025
      for n in 513 1025 2049; do
        "$build/native/fracterra" terrain --method fbm --size "$n" --seed 1 --hurst 0.8 --out "$out/fbm_$n.npy"
        for rep in 1 2 3; do
          run land "$build/native/fracterra" erode --in "$out/fbm_$n.npy" --preset land --threads 2 --stats
        done
      done ;;
    memory)
      # Peak RSS of `terrain --erode land` (the pipeline in memory, no maps)
      # at levels 12 and 13 (docs/measurements/eroded_windows.md).
      for levels in 12 13; do
        run memory /usr/bin/time -v "$build/native/fracterra" terrain --method midpoint --levels "$levels" --seed 1 \
          --erode land --threads 2 --out "$out/memory_$levels.npy"
        rm -f "$out/memory_$levels.npy"
      done ;;
    eroded_tiles)
      # docs/measurements/scale.md: an eroded set on Dask (2 workers) against the in-memory erosion
      # of the same terrain, alternated, 3 of each (not in the default list: minutes at 2049^2,
      # an hour at 8193^2; add 8193 with --levels 13 --memory-limit 10GB on a quiet machine).
      run eroded_tiles env PYTHONPATH="$build/python/stage_linux_x86_64" FRACTERRA_LIBRARY="$build/native/libfracterra.so" \
        /usr/bin/python3 native/bench/tiles_dask_bench.py --erode land --levels 11 --tile 1024 --workers 2 \
        --memory-limit 4GB --reps 3 --out "$out/eroded2049" ;;
    *) echo "unknown section: $s" >&2; exit 2 ;;
  esac
done
