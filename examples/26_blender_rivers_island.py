# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: the add-on's Island preset eroded by Gentle Valleys, with
its Rivers and Lakes, rendered by Cycles (docs/images/rivers-blender.png).

    blender -b --factory-startup --python examples/26_blender_rivers_island.py -- --out OUT

The Island preset's settings (its preset file) at Detail Levels 8, Erosion
Gentle Valleys, Rivers and Lakes with a channel head at 0.8 world units^2 and
widths 0.1 Q^b, the add-on's own terrain and water materials, a sun, a sky and
a camera looking down on the island from the south. Writes OUT/rivers.png.
Exits non-zero with a message on any error.
"""

import importlib.util
import os
import sys
from pathlib import Path

import bpy

HERE = Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("blender_presets_22", HERE / "22_blender_presets.py")
presets22 = importlib.util.module_from_spec(_spec)  # its preset reader, and example 20's scene helpers
_spec.loader.exec_module(presets22)
scene20 = presets22.scene20


def main():
    p = scene20.example_parser("26_blender_rivers_island.py", __doc__, "560x420")
    args = scene20.parse_example(p)
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    print(f"26_blender_rivers_island: {scene20.enable_addon(args.library)}")
    presets22.clear()
    values = presets22.preset_values(presets22.PRESETS / "Island.py")
    values.update(levels=8, erode_preset="VALLEYS")
    if bpy.ops.mesh.fracterra_terrain_add(location=(0, 0, 0), **values) != {"FINISHED"}:
        raise RuntimeError("Island: the terrain operator did not finish")
    terrain = bpy.context.active_object
    s = terrain.fracterra_terrain
    s.rivers_min_area, s.rivers_width_coefficient = 0.8, 0.1
    if bpy.ops.object.fracterra_rivers() != {"FINISHED"}:
        raise RuntimeError("Rivers and Lakes did not finish")
    size = s.world_size
    zs = [v.co.z for v in terrain.data.vertices]
    scene20.sun_camera_render(args, out / "rivers.png", size, zs, back=0.6, up=0.33, lens=30, target_y=0.04)
    print(f"26_blender_rivers_island: highest {max(zs):.2f} m, wrote {out / 'rivers.png'}")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # noqa: BLE001 - any failure is a message and exit code 1
        print(f"26_blender_rivers_island: error: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)  # as example 22: leaves Blender at once, with the code
