# SPDX-License-Identifier: GPL-3.0-or-later
"""No format loses the world size: every writer records it and every reader
gives it back, .npy in a sidecar "<file>.npy.json" (as RAW16's .raw.json);
a file that records none is worked on in the default world, 10 units, with a
one-line warning on stderr. Erosion and rivers are in world units, so a lost
world size would silently make another terrain."""

import json
import subprocess

import numpy as np
import pytest

from test_params import _cli


def run(*args):
    r = subprocess.run([_cli(), *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r


def test_every_format_records_the_world_size(tmp_path):
    # Read back by `coastline --world`, which refuses a file without a world size: x spans it.
    have = run("terrain", "--help").stdout
    exts = [e for e in ("png", "pgm", "npy", "raw", "tif", "exr") if f".{e}" in have]
    assert {"png", "pgm", "npy", "raw"} <= set(exts)
    for ext in exts:
        path = tmp_path / f"t.{ext}"
        run("terrain", "--method", "midpoint", "--levels", 4, "--world-size", 20, "--out", path)
        r = run("coastline", "--in", path, "--level", "q0.5", "--world", "--out", tmp_path / f"{ext}.json")
        xs = [p[0] for line in json.loads((tmp_path / f"{ext}.json").read_text())["polylines"] for p in line["points"]]
        assert 10 < max(xs) <= 20, ext
        assert "warning" not in r.stderr, (ext, r.stderr)


def test_an_npy_round_trip_erodes_in_its_world(tmp_path):
    run("terrain", "--method", "midpoint", "--levels", 5, "--seed", 4, "--world-size", 20, "--out", tmp_path / "t.npy")
    side = json.loads((tmp_path / "t.npy.json").read_text())
    assert side == {"format": "npy", "width": 33, "height": 33, "world_size": 20}
    run("erode", "--in", tmp_path / "t.npy", "--preset", "rugged_mountains", "--out", tmp_path / "e.npy")
    run("terrain", "--method", "midpoint", "--levels", 5, "--seed", 4, "--world-size", 20, "--erode",
        "rugged_mountains", "--out", tmp_path / "want.npy")
    assert np.array_equal(np.load(tmp_path / "e.npy"), np.load(tmp_path / "want.npy"))
    # Without the sidecar: the default world, said once on stderr, and another terrain.
    (tmp_path / "t.npy.json").unlink()
    r = run("erode", "--in", tmp_path / "t.npy", "--preset", "rugged_mountains", "--out", tmp_path / "e10.npy")
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "t.npy' records no world size" in lines[0] and "10 world units" in lines[0], r.stderr
    assert not np.array_equal(np.load(tmp_path / "e10.npy"), np.load(tmp_path / "want.npy"))
    # --world-size given: no warning.
    r = run("rivers", "--in", tmp_path / "t.npy", "--world-size", 20, "--stats")
    assert "warning" not in r.stderr


def test_a_stale_or_broken_sidecar_is_refused(tmp_path):
    run("terrain", "--method", "midpoint", "--levels", 5, "--world-size", 20, "--out", tmp_path / "t.npy")
    np.save(tmp_path / "t.npy", np.zeros((8, 9), np.float32))  # another program replaced the array
    r = subprocess.run([_cli(), "erode", "--in", str(tmp_path / "t.npy"), "--preset", "land", "--stats"],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "describes a 33 x 33 array" in r.stderr and "holds 9 x 8" in r.stderr
    (tmp_path / "t.npy.json").write_text('{"world_size": -3}')
    r = subprocess.run([_cli(), "erode", "--in", str(tmp_path / "t.npy"), "--preset", "land", "--stats"],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "world_size -3" in r.stderr


def test_other_commands_warn_too(tmp_path):
    run("terrain", "--method", "midpoint", "--levels", 6, "--seed", 3, "--out", tmp_path / "plain.npy")
    (tmp_path / "plain.npy.json").unlink()  # as another program's .npy
    for args in (("rivers", "--in", tmp_path / "plain.npy", "--stats"),
                 ("splat", "--in", tmp_path / "plain.npy", "--out", tmp_path / "s.png"),
                 ("analyze", tmp_path / "plain.npy", "--drainage")):
        r = run(*args)
        assert r.stderr.count("records no world size") == 1, (args, r.stderr)
