# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared by the Blender tests that need a window (under Xvfb): checks that
collect failures, the 3D view to run operators in, a hash of a mesh's
heights, waiting for background jobs, and the event loop that runs a test's
steps (a generator yielding seconds to wait) from a timer, as a user's clicks
run, then exits with the outcome (Blender would swallow an exit code)."""

import array
import os
import traceback
import zlib

import bpy

import addon_harness

FAILURES = []
PREFIX = "CHECK FAILED: "  # a test names itself: "GUI CHECK FAILED: "


def check(condition, message, verbose=False):
    """Records a failed check (printed at once); `verbose` prints the passed ones too."""
    if not condition:
        FAILURES.append(message)
        print(f"{PREFIX}{message}", flush=True)
    elif verbose:
        print(f"ok: {message}", flush=True)


def view3d():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    return window, area, region


def in_view3d(region_type="WINDOW"):
    window, area, _ = view3d()
    region = next(r for r in area.regions if r.type == region_type)
    return bpy.context.temp_override(window=window, area=area, region=region)


def heights(obj):
    co = array.array("f", [0.0]) * (3 * len(obj.data.vertices))
    obj.data.vertices.foreach_get("co", co)
    return co[2::3]


def vertex_hash(obj):
    return zlib.crc32(heights(obj).tobytes())


def wait_for_jobs(limit=60.0, then=0.4):
    """Waits while an operator runs in the background (jobs.JobOperator), then `then` seconds."""
    jobs = addon_harness.submodule("blender.common.jobs")
    waited = 0.0
    while jobs.busy() and waited < limit:
        yield 0.1
        waited += 0.1
    check(not jobs.busy(), f"a background job still ran after {limit} s")
    yield then


def run_in_event_loop(steps, name, at_end=None):
    """Runs the generator `steps` from a Blender timer, one step per tick, then
    exits: 0 when no check failed and nothing raised. `at_end()` prints extra lines."""
    def tick():
        try:
            return next(steps)
        except StopIteration:
            outcome = 1 if FAILURES else 0
        except Exception:
            traceback.print_exc()
            outcome = 1
        if at_end is not None:
            at_end()
        print(f"{name} " + ("FAILED: " + "; ".join(FAILURES) if outcome else "passed"), flush=True)
        os._exit(outcome)

    bpy.app.timers.register(tick, first_interval=1.0)
