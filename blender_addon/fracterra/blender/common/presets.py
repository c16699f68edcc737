# SPDX-License-Identifier: GPL-3.0-or-later
"""Operator presets shipped in the add-on's presets/ folder are copied into the
user's preset folder on register (Blender only lists presets from there);
files the user already has are never overwritten.

Earlier versions shipped lowercase presets (alpine_ridges.py, ...). They
linger in users' folders beside the capitalised ones and would show twice,
one of them with old settings (e.g. use_sea_level, gone since the sea moved
into the library). On register they are removed, but only when a file is
byte for byte one the add-on shipped: a preset the user edited, or made
under any other name, is theirs and stays."""

import hashlib
import shutil
from pathlib import Path

import bpy

BUNDLED = Path(__file__).resolve().parents[2] / "presets"

# Presets the add-on no longer ships: path under the user's presets folder ->
# SHA-256 of every version it shipped (the lowercase ones before commit ba1d7c2).
_TERRAIN = "operator/mesh.fracterra_terrain_add/"
RETIRED = {
    _TERRAIN + "alpine_ridges.py": {"4c0982df50b7cff743be28aaaa9245b98936721c19cb119a052bdc6a8c3f2f77"},
    _TERRAIN + "archipelago.py": {"8688e327256681a7840c9eba4f9a6990d30f9ae7753576417e480be2fa45ccca"},
    _TERRAIN + "feder_landscape.py": {"24e200401858fa33636e52f081f82004a066acf18310823dbab38b9bbe0843d3"},
    _TERRAIN + "ridged_mountains.py": {"0d613216080c31dc0c45857a87619b77541bb6febdc825e81671e09927fea7d3"},
    _TERRAIN + "rough_badlands.py": {"82aa2102df3d496d25b855e72175a42bcd79aebaadd742a968a7626a8a58433c"},
    _TERRAIN + "tileable_ground.py": {"d7cc823d8847b20d23b8e5b1cb2b8ce81fa39ba927830b52cf3d44a85525d02a"},
    # Named after a paper's author, not after what it makes (issue 24): now Lake Country.
    _TERRAIN + "Feder Landscape.py": {"48d36501ecad947d30fb717e2a6de8c0315d10340062b9f249c52f2174ea7643"},
}


def user_presets_dir(rel_dir, create=False):
    """The user's folder for presets under `rel_dir` (e.g. operator/mesh.fracterra_terrain_add), or None."""
    path = bpy.utils.user_resource("SCRIPTS", path=str(Path("presets") / rel_dir), create=create)
    return Path(path) if path else None


def remove_retired_presets():
    """Removes the add-on's own retired presets from the user's folder; returns the paths removed."""
    removed = []
    for rel, hashes in RETIRED.items():
        folder = user_presets_dir(Path(rel).parent)
        target = folder / Path(rel).name if folder is not None else None
        if target is None or not target.is_file():
            continue
        if hashlib.sha256(target.read_bytes()).hexdigest() in hashes:
            target.unlink()
            removed.append(target)
        else:
            print(f"fracterra: kept {target}: an old preset name, but edited (not as the add-on shipped it)")
    return removed


def install_presets():
    remove_retired_presets()
    if not BUNDLED.is_dir():
        return
    for src in BUNDLED.rglob("*.py"):
        rel = src.relative_to(BUNDLED)
        target = user_presets_dir(rel.parent, create=True) / rel.name
        if not target.exists():
            shutil.copyfile(src, target)
