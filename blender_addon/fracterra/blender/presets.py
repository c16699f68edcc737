"""Operator presets shipped in the add-on's presets/ folder are copied into the
user's preset folder on register (Blender only lists presets from there);
files the user already has are never overwritten."""

import shutil
from pathlib import Path

import bpy

BUNDLED = Path(__file__).resolve().parent.parent / "presets"


def install_presets():
    if not BUNDLED.is_dir():
        return
    for src in BUNDLED.rglob("*.py"):
        rel = src.relative_to(BUNDLED)
        target_dir = Path(bpy.utils.user_resource("SCRIPTS", path=str(Path("presets") / rel.parent), create=True))
        target = target_dir / rel.name
        if not target.exists():
            shutil.copyfile(src, target)
