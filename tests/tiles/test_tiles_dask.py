"""Tile sets on Dask with real worker processes (dask.distributed LocalCluster).

Every comparison is byte for byte against a tile set written by the
one-process CLI (`fracterra tiles`), the reference: tiles, manifest, VRT and
its overviews.
"""

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "blender_addon"))
if not os.environ.get("FRACTERRA_LIBRARY"):
    os.environ["FRACTERRA_LIBRARY"] = str(ROOT / "build" / "native" / "libfracterra.so")
CLI = os.environ.get("FRACTERRA_CLI", str(ROOT / "build" / "native" / "fracterra"))

from fracterra.core import tiles  # noqa: E402
from fracterra.core.errors import FracterraError  # noqa: E402

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


def test_a_killed_worker_changes_nothing(reference, client, tmp_path):
    pids = client.run(os.getpid)
    killed = []

    def kill_one(c, done, total):
        if done == 3 and not killed:
            victim = sorted(pids.values())[0]
            os.kill(victim, signal.SIGKILL)  # a real worker process, mid-run
            killed.append(victim)

    summary = tiles.build_tileset(SETTINGS, tmp_path / "set", TILE, client=client, progress=False, on_tile=kill_one)
    assert killed, "no worker was killed"
    assert summary["written"] == 16
    # The nanny started a new worker process in its place.
    assert killed[0] not in client.run(os.getpid).values()
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
    # `python3 -m fracterra.core.tiles`: its tasks must reach the workers as references to
    # the package module (a task defined in __main__ would not unpickle there).
    env = dict(os.environ, PYTHONPATH=str(ROOT / "blender_addon"))
    run = subprocess.run([sys.executable, "-m", "fracterra.core.tiles", *FLAGS, "--tile", str(TILE), "--quiet",
                          "--workers", "2", "--memory-limit", "1GB", "--out", str(tmp_path / "set")],
                         capture_output=True, text=True, env=env, timeout=240)
    assert run.returncode == 0, run.stderr
    assert '"written": 16' in run.stdout
    got = files(tmp_path / "set")
    for name in reference:
        assert got[name] == reference[name], name


def test_unreachable_scheduler_is_a_clear_error():
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    env = dict(os.environ, PYTHONPATH=str(ROOT / "blender_addon"))
    run = subprocess.run([sys.executable, "-m", "fracterra.core.tiles", *FLAGS, "--tile", "256", "--out", "unused",
                          "--scheduler", f"tcp://127.0.0.1:{port}", "--connect-timeout", "2"],
                         capture_output=True, text=True, env=env, timeout=120)
    assert run.returncode == 2
    assert f"cannot reach the Dask scheduler at tcp://127.0.0.1:{port} within 2" in run.stderr
    assert "Traceback" not in run.stderr
