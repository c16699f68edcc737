# SPDX-License-Identifier: GPL-3.0-or-later
"""How steadily the bar moves: Add Terrain at Detail Levels N with an erosion
preset, driven as the modal operator drives it (jobs.Runner: the worker
thread, then build steps within 0.05 s ticks). Prints the library's progress
callbacks (seconds: fraction), the bar every 5 %, and the largest gaps
between callbacks and between bar changes (docs/erosion.md, Blender).

    BLENDER_USER_SCRIPTS=/tmp/us blender -b --factory-startup --python scripts/blender_progress_gaps.py \
        -- --zip build/blender_addon/fracterra.zip --levels 12 --preset LAND
"""
import os, sys, time
import bpy
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "blender"))
import addon_harness
argv = sys.argv[sys.argv.index("--") + 1:]
levels, preset = int(argv[argv.index("--levels") + 1]), argv[argv.index("--preset") + 1]
addon_harness.install_and_enable(argv[argv.index("--zip") + 1])
jobs = addon_harness.submodule("blender.common.jobs")
build = addon_harness.submodule("blender.build.terrain")
core = addon_harness.submodule("core")
addon_harness.clear_scene()
values = core.params.defaults()
values.update(levels=levels, erode_preset=preset)
shown = core.erosion.preset_values(preset.lower()) if preset != "NONE" else {}  # as picking it does
values.update({k: v for k, v in shown.items() if k in values})
calls = []
runner = jobs.Runner(build.new_terrain_job(values, bpy.context))
orig = runner._progress
def spy(f):
    calls.append((time.perf_counter(), float(f)))
    return orig(f)
runner._progress = spy
t0 = time.perf_counter()
runner.start()
samples = [(0.0, 0.0)]
state = jobs.RUNNING
while state == jobs.RUNNING:
    tick_end = time.perf_counter() + 0.05
    state = runner.step()
    while state == jobs.RUNNING and runner.working_done and time.perf_counter() < tick_end:
        state = runner.step()
    now = time.perf_counter() - t0
    if runner.fraction != samples[-1][1]:
        samples.append((now, runner.fraction))
    time.sleep(max(0.0, tick_end - time.perf_counter()))
end = time.perf_counter() - t0
samples.append((end, 1.0))
gaps = [(b[0] - a[0], a[0], a[1]) for a, b in zip(samples, samples[1:])]
worst = max(gaps)
cgaps = [(b[0] - a[0], a[0] - t0, a[1]) for a, b in zip(calls, calls[1:])]
cworst = max(cgaps) if cgaps else (0, 0, 0)
print(f"RESULT levels {levels} {preset}: {state}, {end:.1f} s, {len(calls)} library callbacks, "
      f"largest callback gap {cworst[0]:.2f} s at {cworst[1]:.1f} s (fraction {cworst[2]:.3f}); "
      f"bar: {len(samples)} changes, largest gap {worst[0]:.2f} s at {worst[1]:.1f} s (bar {worst[2]:.3f})", flush=True)
print("LARGEST BAR GAPS", ", ".join(f"{g:.1f} s from {t:.1f} s (bar {f:.3f})" for g, t, f in sorted(gaps)[-5:][::-1]))
# the bar over time, every ~5%
last = -1
for t, f in samples:
    if int(f * 20) != last:
        last = int(f * 20)
        print(f"  {t:6.2f} s  {f:.3f}")
print("CALLBACKS", " ".join(f"{t - t0:.1f}:{f:.3f}" for t, f in calls))
os._exit(0)  # Blender would wait on its own exit
