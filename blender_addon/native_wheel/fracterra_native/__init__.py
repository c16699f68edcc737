# SPDX-License-Identifier: GPL-3.0-or-later
"""The fracterra add-on's native library, as Blender 4.2+ installs it from the
extension's wheel: LIBRARY_DIR holds libfracterra.so (or fracterra.dll) and
the libraries it bundles. core/binding.py finds this folder without importing it."""

from pathlib import Path

LIBRARY_DIR = Path(__file__).resolve().parent / "lib"
