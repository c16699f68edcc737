# SPDX-License-Identifier: GPL-3.0-or-later
"""pytest set-up: the add-on's bpy-free core is imported straight from the
source tree; the library comes from FRACTERRA_LIBRARY (set by ctest to the
freshly built libfracterra.so)."""

import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "blender_addon"))


def pytest_configure(config):
    if not os.environ.get("FRACTERRA_LIBRARY"):
        built = ROOT / "build" / "native" / "libfracterra.so"
        if built.is_file():
            os.environ["FRACTERRA_LIBRARY"] = str(built)


@pytest.fixture(scope="session")
def core():
    import fracterra.core as core
    core.library()  # fail early with the loader's message
    return core


@pytest.fixture(scope="session")
def header_dir():
    return ROOT / "native" / "include" / "fracterra"
