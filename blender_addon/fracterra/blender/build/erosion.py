# SPDX-License-Identifier: GPL-3.0-or-later
"""The Erode step of a terrain in Blender: the settings a preset runs with,
erosion after generation (in the job's worker thread), the terrain's colours by
its splat rules (splat_material.py) and the maps as mesh point attributes.
(Its settings are drawn by ui/erosion_layout.py.)
"""

import numpy as np

from ... import core
from ...core import erosion, params
from ...core import splat as splat_rules
from . import splat_material

# Point attributes (0..1) beside fracterra_height and fracterra_slope.
FLOW_ATTRIBUTE = "fracterra_flow"  # log drainage area: 0 on ridges, 1 at the main outlet
DEPOSIT_ATTRIBUTE = "fracterra_deposit"  # sediment laid down
WATER_ATTRIBUTE = "fracterra_water"  # water left by the rain
ATTRIBUTES = (FLOW_ATTRIBUTE, DEPOSIT_ATTRIBUTE, WATER_ATTRIBUTE)


# --- in the job's worker thread (no bpy here)

# The work's bar by the parts' times at 4097^2 (Rugged Mountains, load 4-6):
# the library's pipeline, the mesh arrays with the height and slope
# attributes, the colours, the maps' attributes.
LIBRARY_SHARE, ARRAYS_SHARE, COLORS_SHARE = 0.75, 0.12, 0.11

def generate_and_erode(values, reference, progress, threads, grid_of, falloff_mask=None, maps=None, rules=None):
    """Builds the terrain of `values` (with its reference and falloff mask, as
    core.generate_terrain takes them) in one library call, eroded when its
    settings ask for it (a preset: its run and rates, Strength and the rest as
    set; Custom: everything as set), where `maps` say (erosion_masks.maps_for:
    the erosion mask and the rain map, or None); returns grid_of(heightfield)
    with `.erosion_maps` ({attribute: float32 array} or None), `.water`
    (core.rivers.WaterArrays, or None without Rivers and Lakes) and `.colors`
    (linear RGBA per sample by the splat `rules`, core.splat.Rules; None: the
    built-in set). Runs in the worker thread."""
    preset = values.get("erode_preset", "NONE")
    eroded = preset not in ("NONE", "CUSTOM") or (preset == "CUSTOM" and erosion.requested(values))
    # The bar: the library's pipeline, then the mesh arrays (seconds at 4097^2).
    cancelled = [False]

    def part(start, span):
        def report(fraction):
            cancelled[0] = bool(progress(start + span * fraction)) or cancelled[0]
            return cancelled[0]
        return report

    # With Rivers and Lakes on, the pipeline's last stage traces them too (water.py builds them).
    hf, maps, water = core.build_terrain_rivers(values, params.RIVERS_PARAMS if values.get("rivers") else None,
                                                reference=reference, falloff_mask=falloff_mask,
                                                erosion=values if eroded else None,
                                                preset="NONE" if preset == "CUSTOM" else preset, maps=eroded,
                                                threads=threads, progress=part(0.0, LIBRARY_SHARE),
                                                **(maps if eroded and maps else {}))
    with hf:
        g = grid_of(hf, part(LIBRARY_SHARE, ARRAYS_SHARE))
        if cancelled[0]:
            raise core.CancelledError("Generating terrain: cancelled", core.errors.FT_ERR_CANCELLED)
        spacing = values["world_size"] / (hf.width - 1)
        # The library's colour map of the final heights and maps: what the
        # material shows and the POV-Ray export paints.
        g.colors = splat_material.linear_colors(hf, rules if rules is not None else splat_rules.default_rules(),
                                                maps if eroded else None, threads=threads,
                                                progress=part(LIBRARY_SHARE + ARRAYS_SHARE, COLORS_SHARE))
    g.erosion_maps = None
    g.water = water
    if eroded:
        g.erosion_maps = attribute_maps({k: np.frombuffer(v, dtype=np.float32) for k, v in maps.items()},
                                        spacing * spacing)
    part(0.0, 1.0)(1.0)
    if cancelled[0]:
        raise core.CancelledError("Generating terrain: cancelled", core.errors.FT_ERR_CANCELLED)
    return g


def _robust_unit(values):
    """values over the 99th percentile of the positive ones, clipped to 0..1: a few
    extreme cells (a lake, the outlet) must not squash all others to 0."""
    positive = values[values > 0]
    scale = float(np.percentile(positive, 99)) if positive.size else 0.0
    if scale <= 0:
        return np.zeros_like(values, dtype=np.float32)
    return np.clip(values / scale, 0.0, 1.0).astype(np.float32)


def attribute_maps(maps, cell_area):
    """The library's maps (world units) as 0..1 attributes by name:
    fracterra_flow: log of the drainage area in cells over the log of the largest
    (0: a ridge cell drains only itself, 1: the largest outlet);
    fracterra_deposit, fracterra_water: deposited sediment and water left, each
    over its 99th percentile, clipped."""
    cells = np.maximum(maps["drainage_area"] / cell_area, 1.0)
    top = float(np.log(cells.max()))
    flow = (np.log(cells) / top).astype(np.float32) if top > 0 else np.zeros_like(cells, dtype=np.float32)
    return {FLOW_ATTRIBUTE: flow, DEPOSIT_ATTRIBUTE: _robust_unit(maps["deposited"]),
            WATER_ATTRIBUTE: _robust_unit(maps["water_depth"])}


# --- in the main thread (build steps)

def set_maps(mesh, maps):
    """Writes the erosion attributes of a terrain mesh, or removes them when it
    was not eroded (so a material never shows stale channels)."""
    for name in ATTRIBUTES:
        layer = mesh.attributes.get(name)
        if maps is None:
            if layer is not None:
                mesh.attributes.remove(layer)
            continue
        if layer is None:
            layer = mesh.attributes.new(name, "FLOAT", "POINT")
        layer.data.foreach_set("value", maps[name])
