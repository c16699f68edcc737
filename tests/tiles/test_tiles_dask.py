# SPDX-License-Identifier: GPL-3.0-or-later
"""Tile sets on Dask with real worker processes (dask.distributed LocalCluster),
driven by the Python package's fracterra.tiles as pip installed it in a venv.

Every comparison is byte for byte against a tile set written by the
one-process CLI (`fracterra tiles`), the reference: tiles, manifest, VRT and
its overviews.
"""

import os
import signal
import socket
import subprocess
import sys
from pathlib import Path

import cloudpickle
import pytest
from distributed.diagnostics.plugin import WorkerPlugin

from fracterra import FracterraError, tiles  # the installed wheel's package (tests/package/run_in_venv.py)

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("FRACTERRA_CLI", str(ROOT / "build" / "native" / "fracterra"))

# 1025^2 midpoint in 16 tiles of 257^2 (the overviews: 513 and 257 a side).
SETTINGS = {"method": "MIDPOINT", "levels": 10, "hurst": 0.75, "seed": 42}
FLAGS = ["--method", "midpoint", "--levels", "10", "--hurst", "0.75", "--seed", "42"]
TILE = 256


def files(folder):
    """{name: bytes} of every file in a tile set folder."""
    return {p.name: p.read_bytes() for p in sorted(Path(folder).iterdir()) if p.is_file()}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The tile set written by one process (the CLI)."""
    out = tmp_path_factory.mktemp("cli") / "set"
    subprocess.run([CLI, "tiles", *FLAGS, "--tile", str(TILE), "--quiet", "--out", str(out)], check=True,
                   capture_output=True)
    return files(out)


@pytest.fixture(scope="module")
def client():
    c = tiles.connect(workers=2, memory_limit="1GB")
    yield c
    cluster = c.cluster
    c.close()
    cluster.close()


def test_localcluster_writes_the_same_bytes_as_one_process(reference, client, tmp_path):
    assert len(client.scheduler_info()["workers"]) == 2
    summary = tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False)
    assert summary["written"] == 16
    got = files(tmp_path / "set")
    assert sorted(got) == sorted(reference)
    assert {"manifest.json", "mosaic.vrt", "mosaic.vrt.ovr"} <= set(got)
    for name in reference:
        assert got[name] == reference[name], name
    # Both workers took part (one task per tile, spread over the cluster).
    assert len(summary["worker_peak_rss_mib"]) == 2


class TaskMarkers(WorkerPlugin):
    """On every worker: an empty file KEY.PID.start when a tile task starts executing there, and
    KEY.PID.end when its result is in the worker's memory (creating a file is atomic)."""

    def __init__(self, folder):
        self.folder = folder

    def transition(self, key, start, finish, **kwargs):
        if not str(key).startswith("fracterra-tile-"):
            return
        tag = "start" if finish == "executing" else "end" if (start, finish) == ("executing", "memory") else None
        if tag:
            open(os.path.join(self.folder, f"{key}.{os.getpid()}.{tag}"), "w").close()


def marked(folder, pid, tag):
    return {p.name.split(".")[0] for p in Path(folder).glob(f"*.{pid}.{tag}")}


def test_a_killed_worker_changes_nothing(reference, client, tmp_path):
    # The worker is killed while a task is provably running on it: it is
    # frozen (SIGSTOP) first, and killed only if the markers show a task that
    # started there and has no result yet (else it resumes, and the next
    # finished tile tries again). That task must then run again elsewhere.
    marks = tmp_path / "marks"
    marks.mkdir()
    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # workers cannot import this file
    client.register_worker_plugin(TaskMarkers(str(marks)), name="task-markers")
    victim = sorted(client.run(os.getpid).values())[0]
    lost = []

    def kill_one(c, done, total):
        if lost:
            return
        os.kill(victim, signal.SIGSTOP)
        running = marked(marks, victim, "start") - marked(marks, victim, "end")
        if running:
            os.kill(victim, signal.SIGKILL)  # a real worker process, mid-task
            lost.extend(running)
        else:
            os.kill(victim, signal.SIGCONT)

    try:
        summary = tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False,
                                      on_tile=kill_one)
    finally:
        client.unregister_worker_plugin("task-markers")
    assert lost, "the worker never had a task in flight when a tile finished"
    assert summary["written"] == 16
    # The nanny started a new worker process in its place, and every lost
    # task ran to its end on a live worker.
    assert victim not in client.run(os.getpid).values()
    for key in lost:
        assert key not in marked(marks, victim, "end")
        assert [p for p in marks.glob(f"{key}.*.end")], f"{key} was lost with the worker and never run again"
    got = files(tmp_path / "set")
    assert sorted(got) == sorted(reference)  # no temporary file left behind
    for name in reference:
        assert got[name] == reference[name], name


class DriverKilled(Exception):
    pass


def test_a_killed_driver_resumes(reference, client, tmp_path):
    def stop(c, done, total):
        if done == 5:
            raise DriverKilled()

    with pytest.raises(DriverKilled):
        tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False, on_tile=stop)
    summary = tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False)
    assert summary["skipped"] >= 5
    assert summary["written"] + summary["skipped"] == 16
    got = files(tmp_path / "set")
    for name in reference:
        assert got[name] == reference[name], name


def test_the_exact_height_range_pass_runs_on_dask(client, tmp_path):
    # Additions have no cheap coarse stage: the range is the exact union of the
    # tiles' ranges, here one Dask task per tile, and the set equals the one-process CLI's.
    cli = tmp_path / "cli"
    subprocess.run([CLI, "tiles", "--method", "additions", "--levels", "9", "--hurst", "0.6", "--seed", "3",
                    "--tile", "128", "--quiet", "--out", str(cli)], check=True, capture_output=True)
    settings = {"method": "ADDITIONS", "levels": 9, "hurst": 0.6, "seed": 3}
    summary = tiles.build_tileset(settings, tmp_path / "set", 128, client=client, progress=False)
    assert "range_seconds" in summary  # the pass ran as tasks, not in the library's open
    assert client.run_on_scheduler(
        lambda dask_scheduler: sum(1 for k in dask_scheduler.task_prefixes if k.startswith("fracterra-range")))
    want = files(cli)
    got = files(tmp_path / "set")
    assert sorted(got) == sorted(want)
    for name in want:
        assert got[name] == want[name], name


def test_another_terrains_folder_is_refused(client, tmp_path):
    tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False)
    with pytest.raises(FracterraError, match=r"holds another tile set \(seed: 43 here, 42 in the folder\)"):
        tiles.build_tileset(dict(SETTINGS, seed=43), tmp_path / "set", TILE, client=client, progress=False)


def test_hurst_from_tile_sums_reduced_on_dask_equals_the_whole(client):
    from fracterra.core import generate_terrain, hurst_of_heightfield
    got = tiles.measure_tileset(SETTINGS, 64, client)  # 1025^2: default lags 1..64
    with generate_terrain(SETTINGS) as whole:
        want = hurst_of_heightfield(whole, method="VARIOGRAM_ALIGNED")
    assert got["hurst"] == pytest.approx(want["hurst"], abs=1e-12)
    assert got["dimension"] == pytest.approx(3.0 - want["hurst"], abs=1e-12)
    assert got["lag_max"] == 64


def test_the_command_line_driver_writes_the_same_bytes(reference, tmp_path):
    # `python3 -m fracterra.tiles`: its tasks must reach the workers as references to
    # the package's modules (a task defined in __main__ would not unpickle there).
    run = subprocess.run([sys.executable, "-m", "fracterra.tiles", *FLAGS, "--tile", str(TILE), "--quiet",
                          "--workers", "2", "--memory-limit", "1GB", "--out", str(tmp_path / "set")],
                         capture_output=True, text=True, timeout=240)
    assert run.returncode == 0, run.stderr
    assert '"written": 16' in run.stdout
    got = files(tmp_path / "set")
    for name in reference:
        assert got[name] == reference[name], name


# An eroded 257^2 mountain with its maps in 16 tiles of 65^2 (Rugged Mountains, Strength 0.7).
ERODED = {"method": "MIDPOINT", "levels": 8, "seed": 5, "sigma": 2.0, "levelling": 1.0, "height_offset": 1.5,
          "falloff": "RADIAL", "falloff_width": 0.9, "world_size": 10.0}
ERODED_FLAGS = ["--method", "midpoint", "--levels", "8", "--seed", "5", "--sigma", "2", "--levelling", "1",
                "--height-offset", "1.5", "--falloff", "radial", "--falloff-width", "0.9", "--world-size", "10",
                "--erode", "land", "--strength", "0.7", "--maps"]


def all_files(folder):
    """{relative name: bytes} of every file under a tile set folder (its maps too)."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(Path(folder).rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def eroded_reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli-eroded") / "set"
    subprocess.run([CLI, "tiles", *ERODED_FLAGS, "--tile", "64", "--quiet", "--out", str(out)], check=True,
                   capture_output=True)
    return all_files(out)


def test_an_eroded_set_on_dask_is_the_one_process_set_even_with_a_worker_killed(eroded_reference, client,
                                                                               tmp_path):
    # The range pass (one task per tile, each keeping its eroded tile) and the
    # writing pass run on the cluster; a worker is killed while a tile task is
    # provably running on it (as in test_a_killed_worker_changes_nothing). Every
    # file, heights, maps, manifest and mosaics, equals the CLI's.
    marks = tmp_path / "marks"
    marks.mkdir()
    cloudpickle.register_pickle_by_value(sys.modules[__name__])
    client.register_worker_plugin(TaskMarkers(str(marks)), name="task-markers")
    victim = sorted(client.run(os.getpid).values())[0]
    lost = []

    def kill_one(c, done, total):
        if lost:
            return
        os.kill(victim, signal.SIGSTOP)
        running = marked(marks, victim, "start") - marked(marks, victim, "end")
        if running:
            os.kill(victim, signal.SIGKILL)
            lost.extend(running)
        else:
            os.kill(victim, signal.SIGCONT)

    try:
        summary = tiles.build_tileset(ERODED, tmp_path / "set", 64, client=client, progress=False,
                                      preset="LAND", erosion={"strength": 0.7}, maps=True, on_tile=kill_one)
    finally:
        client.unregister_worker_plugin("task-markers")
    assert "range_seconds" in summary
    assert summary["written"] == 16
    assert lost, "the worker never had a tile task in flight when a tile finished"
    got = all_files(tmp_path / "set")
    assert sorted(got) == sorted(eroded_reference)  # nothing left over: no pending folder, no temporary file
    for name in eroded_reference:
        assert got[name] == eroded_reference[name], name


def test_another_erosion_is_refused(client, tmp_path):
    tiles.build_tileset(ERODED, tmp_path / "set", 64, client=client, progress=False, preset="LAND", maps=True)
    with pytest.raises(FracterraError, match=r"erosion strength: 0.9 here, 0.5 in the folder"):
        tiles.build_tileset(ERODED, tmp_path / "set", 64, client=client, progress=False, preset="LAND",
                            erosion={"strength": 0.9}, maps=True)


def test_unreachable_scheduler_is_a_clear_error():
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    run = subprocess.run([sys.executable, "-m", "fracterra.tiles", *FLAGS, "--tile", "256", "--out", "unused",
                          "--scheduler", f"tcp://127.0.0.1:{port}", "--connect-timeout", "2"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 2
    assert f"cannot reach the Dask scheduler at tcp://127.0.0.1:{port} within 2" in run.stderr
    assert "Traceback" not in run.stderr
