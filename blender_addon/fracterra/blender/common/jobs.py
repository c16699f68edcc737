# SPDX-License-Identifier: GPL-3.0-or-later
"""Long work with a progress bar and Esc to cancel, for any operator.

A Job is split where Blender needs it split:
  - `work(progress)` is bpy-free (library calls, numpy) and runs in a worker
    thread, so the window keeps drawing; `progress(fraction)` returns True
    once the user has cancelled, which is what the library's progress
    callback wants (it then stops, frees what it made and raises
    core.CancelledError);
  - `build(result)` is a generator run in the main thread, one step per
    timer tick, that turns the result into Blender data and yields its own
    progress fractions; cancelling closes it at a yield, so it must undo
    what it made in a `finally`/`except GeneratorExit` (no half-built mesh).
    What it returns (StopIteration.value) goes to the operator.

JobOperator gives an operator both ways to run a job: invoke() runs it in
the background (modal, status-bar progress, Esc cancels); execute() runs the
same job to the end in the calling thread (the redo panel, scripts,
background Blender). The redo panel blocks the window and can show no bar:
work that outlasts REDO_BUDGET there is cancelled and handed over to the
modal job, started again with the same settings as the menu starts it. Subclasses define make_job(context) and
job_done(context, value); errors in REPORTED become reports, never
tracebacks.

It imports only core, bpy and reporting (a leaf), so every operator module
can use it (the erosion and tile operators too).
"""

import threading
import time

import bpy

from ... import core
from .reporting import REPORTED

RUNNING, FINISHED, CANCELLED = "RUNNING", "FINISHED", "CANCELLED"

# The jobs running modally now (tests wait for it to empty).
ACTIVE = set()


def busy():
    """True while a job runs in the background."""
    return bool(ACTIVE)


class Job:
    """label: what the status bar says; work and build as in the module doc;
    work_share: the part of the bar that work() fills (build() the rest)."""

    def __init__(self, label, work, build=None, work_share=0.8):
        self.label = label
        self.work = work
        self.build = build
        self.work_share = work_share if build is not None else 1.0


def _no_build(result):
    return result
    yield  # noqa: unreachable - makes this a generator


class Runner:
    """Drives one Job: the worker thread, then the build steps. Blender data is
    touched only in step(), which the caller runs in the main thread."""

    def __init__(self, job):
        self.job = job
        self.cancelled = False
        self.work_fraction = 0.0
        self.build_fraction = 0.0
        self.value = None
        self._result = None
        self._error = None
        self._work_done = threading.Event()
        self._thread = None
        self._steps = None
        self.started = time.perf_counter()

    # --- the worker thread
    def _progress(self, fraction):
        self.work_fraction = min(max(float(fraction), 0.0), 1.0)
        return self.cancelled

    def _run_work(self):
        try:
            self._result = self.job.work(self._progress)
        except BaseException as e:  # noqa: B036 - handed to the main thread by step()
            self._error = e
        finally:
            self._work_done.set()

    def start(self):
        self._thread = threading.Thread(target=self._run_work, name=f"fracterra: {self.job.label}", daemon=True)
        self._thread.start()

    # --- the main thread
    def cancel(self):
        """Asks the work to stop; the next step()s return CANCELLED once it has."""
        self.cancelled = True

    @property
    def working_done(self):
        return self._work_done.is_set()

    @property
    def fraction(self):
        share = self.job.work_share
        return share * self.work_fraction + (1.0 - share) * self.build_fraction

    def step(self):
        """Advances by one build step once the work is done. Returns RUNNING,
        FINISHED (self.value holds what build returned) or CANCELLED; raises
        the work's or the build's error."""
        if self._steps is None:
            if not self._work_done.is_set():
                return RUNNING
            self._thread = None
            error, self._error = self._error, None
            if isinstance(error, core.CancelledError) or (error is None and self.cancelled):
                self._result = None  # drop what was made (its handles close with it)
                return CANCELLED
            if error is not None:
                raise error
            result, self._result = self._result, None
            self._steps = (self.job.build or _no_build)(result)
        if self.cancelled:
            self._steps.close()  # GeneratorExit at its yield: it removes what it made
            self._steps = None
            return CANCELLED
        try:
            self.build_fraction = float(next(self._steps))
        except StopIteration as done:
            self._steps = None
            self.value = done.value
            self.build_fraction = 1.0
            return FINISHED
        except BaseException:
            self._steps = None
            raise
        return RUNNING

    def finish(self, on_progress=None):
        """Runs the build steps once the work is done; FINISHED or CANCELLED like step()."""
        while True:
            state = self.step()
            if on_progress is not None:
                on_progress(self.fraction)
            if state != RUNNING:
                return state

    def run_blocking(self, on_progress=None):
        """Runs the whole job in this thread (no cancel but the callback's).
        Returns FINISHED or CANCELLED like step()."""
        def progress(fraction):
            self._progress(fraction)
            if on_progress is not None:
                on_progress(self.fraction)
            return self.cancelled
        try:
            self._result = self.job.work(progress)
        except BaseException as e:  # noqa: B036 - re-raised by step() below, like the thread's
            self._error = e
        self._work_done.set()
        return self.finish(on_progress)

    @property
    def seconds(self):
        return time.perf_counter() - self.started


def run_job(job, on_progress=None):
    """Runs `job` to the end in this thread (auto-update, scripts); returns
    what its build returned."""
    runner = Runner(job)
    if runner.run_blocking(on_progress) == CANCELLED:
        raise core.CancelledError(f"{job.label}: cancelled", core.errors.FT_ERR_CANCELLED)
    return runner.value


def run_timed(job):
    """run_job for a job whose value is a summary: the summary and the seconds it took."""
    t0 = time.perf_counter()
    summary = run_job(job)
    return f"{summary} in {time.perf_counter() - t0:.2f} s"


def status_text(label, fraction, cancelling=False):
    """The status bar's line: a text bar (the status bar takes text only in
    Blender 3.4), the percentage, and how to cancel."""
    cells = 20
    full = int(round(fraction * cells))
    bar = "\u2588" * full + "\u2591" * (cells - full)
    tail = "cancelling..." if cancelling else "Esc: Cancel"
    return f"{label}  {bar}  {int(fraction * 100):3d}%    {tail}"


class StatusBar:
    """The window's progress (wm.progress_*: the cursor) and the status bar's text."""

    def __init__(self, context, label):
        self.wm = context.window_manager
        self.workspace = context.workspace
        self.label = label
        self.wm.progress_begin(0, 1000)

    def update(self, fraction, cancelling=False):
        self.wm.progress_update(int(fraction * 1000))
        if self.workspace is not None:
            self.workspace.status_text_set(status_text(self.label, fraction, cancelling))

    def end(self):
        self.wm.progress_end()
        if self.workspace is not None:
            self.workspace.status_text_set(None)


# Seconds the redo panel may block the window before its work is handed over
# to the modal job (a drag in the redo panel reruns the operator each time).
REDO_BUDGET = 0.5


def operator_arguments(op):
    """{name: value} of every property of operator `op`: what starts it again alike."""
    out = {}
    for name, prop in op.properties.bl_rna.properties.items():
        if name == "rna_type" or prop.is_readonly:
            continue
        value = getattr(op.properties, name)
        out[name] = tuple(value) if getattr(prop, "is_array", False) else value
    return out


class JobOperator:
    """Mixin for bpy.types.Operator: define make_job(context) -> Job (raise a
    REPORTED error to refuse) and job_done(context, value) -> {'FINISHED'}
    (self.job_seconds then holds the job's time, work and build)."""

    job_seconds = 0.0

    _timer_seconds = 0.05

    def make_job(self, context):
        raise NotImplementedError

    def job_done(self, context, value):
        return {"FINISHED"}

    def job_cancelled(self, context):
        """Called when the user cancelled (Esc) or the progress callback did:
        what was made is already gone; put anything else back."""

    def _refuse(self, e):
        self.report({"ERROR"}, str(e))
        return {"CANCELLED"}

    def _redo_in_window(self, context):
        return self.options.is_repeat and getattr(context, "window", None) is not None and not bpy.app.background

    def _hand_over(self, context, runner):
        """Stops the redo's work and starts the operator again as its menu does
        (a modal job: status-bar progress, Esc cancels), once this redo is over."""
        runner.cancel()
        runner._work_done.wait()
        window, area = context.window, context.area
        category, name = self.bl_idname.lower().split("_ot_") if "_OT_" in self.bl_idname else \
            self.bl_idname.split(".")  # MESH_OT_x at run time, mesh.x in the class
        start_again = getattr(getattr(bpy.ops, category), name)
        arguments = operator_arguments(self)

        def start():
            region = next((r for r in area.regions if r.type == "WINDOW"), None) if area else None
            with bpy.context.temp_override(window=window, area=area, region=region):
                start_again("INVOKE_DEFAULT", True, **arguments)
        bpy.app.timers.register(start, first_interval=0.01)
        self.report({"INFO"}, f"{runner.job.label}: longer than {REDO_BUDGET} s, continues with a progress bar "
                              "(Esc cancels)")
        return {"FINISHED"}

    def execute(self, context):
        try:
            job = self.make_job(context)
            runner = Runner(job)
            if self._redo_in_window(context):
                runner.start()
                if not runner._work_done.wait(REDO_BUDGET):
                    return self._hand_over(context, runner)
                state = runner.finish()
            else:
                wm = getattr(context, "window_manager", None)
                if wm is not None:
                    wm.progress_begin(0, 1000)
                try:
                    state = runner.run_blocking(
                        (lambda f: wm.progress_update(int(f * 1000))) if wm is not None else None)
                finally:
                    if wm is not None:
                        wm.progress_end()
        except REPORTED as e:
            return self._refuse(e)
        if state == CANCELLED:
            self.job_cancelled(context)
            self.report({"WARNING"}, f"{job.label}: cancelled")
            return {"CANCELLED"}
        self.job_seconds = runner.seconds
        return self.job_done(context, runner.value)

    def invoke(self, context, event):
        if context.window is None or bpy.app.background:
            return self.execute(context)
        try:
            job = self.make_job(context)
        except REPORTED as e:
            return self._refuse(e)
        self._runner = Runner(job)
        self._status = StatusBar(context, job.label)
        self._status.update(0.0)
        self._runner.start()
        ACTIVE.add(self._runner)
        wm = context.window_manager
        self._timer = wm.event_timer_add(self._timer_seconds, window=context.window)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _end(self, context):
        ACTIVE.discard(self._runner)
        context.window_manager.event_timer_remove(self._timer)
        self._status.end()

    def modal(self, context, event):
        runner = self._runner
        if event.type == "ESC" and event.value == "PRESS":
            runner.cancel()
        if event.type != "TIMER":
            # Every other event waits: nothing may change the scene under a half-done job.
            return {"RUNNING_MODAL"}
        try:
            # Several cheap build steps per tick; the bar still redraws every tick.
            tick_end = time.perf_counter() + self._timer_seconds
            state = runner.step()
            while state == RUNNING and runner.working_done and time.perf_counter() < tick_end:
                state = runner.step()
        except REPORTED as e:
            self._end(context)
            return self._refuse(e)
        except BaseException:
            self._end(context)
            raise
        if state == RUNNING:
            self._status.update(runner.fraction, runner.cancelled)
            return {"RUNNING_MODAL"}
        self._end(context)
        if state == CANCELLED:
            self.job_cancelled(context)
            self.report({"WARNING"}, f"{runner.job.label}: cancelled after {runner.seconds:.1f} s, nothing kept")
            return {"CANCELLED"}
        self.job_seconds = runner.seconds
        return self.job_done(context, runner.value)
