"""The Erode step of a terrain in Blender: the settings a preset runs with,
erosion after generation (in the job's worker thread), the maps as mesh point
attributes and the node material that textures by them. (Its settings are
drawn by ui/erosion_layout.py.)
"""

import bpy
import numpy as np

from ... import core
from ...core import erosion, params
from .mesh import SLOPE_ATTRIBUTE
from .shader_nodes import NodeMaterial

# Point attributes (0..1) beside fracterra_height and fracterra_slope.
FLOW_ATTRIBUTE = "fracterra_flow"  # log drainage area: 0 on ridges, 1 at the main outlet
DEPOSIT_ATTRIBUTE = "fracterra_deposit"  # sediment laid down
WATER_ATTRIBUTE = "fracterra_water"  # water left by the rain
ATTRIBUTES = (FLOW_ATTRIBUTE, DEPOSIT_ATTRIBUTE, WATER_ATTRIBUTE)
MATERIAL_NAME = "Fracterra Eroded Terrain"
# The eroded material's rule (eroded_material's nodes, eroded_colors per sample
# for the POV-Ray export): linear RGB, and the attribute ranges each ramp rises over.
GRASS, SEDIMENT, ROCK = (0.16, 0.26, 0.07), (0.55, 0.47, 0.33), (0.33, 0.31, 0.29)
CHANNELS, DEPOSITS, STEEP = (0.45, 0.7), (0.05, 0.4), (0.3, 0.45)


# --- in the job's worker thread (no bpy here)

# The library's share of the work's bar; the mesh arrays and the maps the rest.
LIBRARY_SHARE = 0.85

def generate_and_erode(values, reference, progress, threads, grid_of, falloff_mask=None, maps=None):
    """Builds the terrain of `values` (with its reference and falloff mask, as
    core.generate_terrain takes them) in one library call, eroded when its
    settings ask for it (a preset: its run and rates, Strength and the rest as
    set; Custom: everything as set), where `maps` say (erosion_masks.maps_for:
    the erosion mask and the rain map, or None); returns grid_of(heightfield)
    with `.erosion_maps` ({attribute: float32 array} or None) and `.water`
    (core.rivers.WaterArrays, or None without Rivers and Lakes). Runs in the
    worker thread."""
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
        g = grid_of(hf, part(LIBRARY_SHARE, 0.95 - LIBRARY_SHARE))
        spacing = values["world_size"] / (hf.width - 1)
    g.erosion_maps = None
    g.water = water
    if eroded:
        g.erosion_maps = attribute_maps({k: np.frombuffer(v, dtype=np.float32) for k, v in maps.items()},
                                        spacing * spacing)
    part(0.95, 0.05)(1.0)
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
    if maps is not None and len(mesh.materials) == 0:
        mesh.materials.append(eroded_material())


def eroded_material():
    """The node material of eroded terrains (made once per file): rock where the
    slope is steep, sediment in channels and on deposits, grass elsewhere, from
    the point attributes fracterra_slope, fracterra_flow and fracterra_deposit."""
    mat = bpy.data.materials.get(MATERIAL_NAME)
    if mat is not None:
        return mat
    m = NodeMaterial(MATERIAL_NAME)
    grass, sediment, rock = (*GRASS, 1.0), (*SEDIMENT, 1.0), (*ROCK, 1.0)
    channels = m.ramp(m.attribute(FLOW_ATTRIBUTE, 200), *CHANNELS, 200)
    deposits = m.ramp(m.attribute(DEPOSIT_ATTRIBUTE, 0), *DEPOSITS, 0)
    wet = m.math("MAXIMUM", channels, deposits, 100)
    steep = m.ramp(m.attribute(SLOPE_ATTRIBUTE, -200), *STEEP, -200)
    ground = m.mix(wet, grass, sediment, 100)
    m.base_color(m.mix(steep, ground, rock, -100))
    mat = m.material
    return mat


def eroded_colors(slope, flow, deposit):
    """eroded_material's base colour at each sample of the attribute arrays
    (0..1 each): an (n, 3) float32 array of linear RGB, node for node."""

    def ramp(x, lo, hi):  # Map Range, smoothstep, clamped
        t = np.clip((np.asarray(x, dtype=np.float64) - lo) / (hi - lo), 0.0, 1.0)
        return (t * t * (3.0 - 2.0 * t))[:, None]

    def mix(fac, a, b):  # MixRGB, Mix
        return (1.0 - fac) * np.asarray(a) + fac * np.asarray(b)

    ground = mix(np.maximum(ramp(flow, *CHANNELS), ramp(deposit, *DEPOSITS)), GRASS, SEDIMENT)
    return mix(ramp(slope, *STEEP), ground, ROCK).astype(np.float32)
