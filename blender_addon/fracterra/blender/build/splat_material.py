# SPDX-License-Identifier: GPL-3.0-or-later
"""A terrain's colour in Blender: the library's splat colour map (core/splat.py,
the rules `fracterra splat` and the POV-Ray export use) as a point colour
attribute, and the node material that reads it. The colours are computed in
the job's worker thread beside the mesh arrays and written, with the material,
in the main thread.
"""

import os

import bpy
import numpy as np

from ... import core
from ...core import splat
from ..common.reporting import SettingsError
from . import huge_pages

COLOR_ATTRIBUTE = "fracterra_color"  # linear RGB(A), one per vertex, in the grid's order
MATERIAL_NAME = "Fracterra Terrain"
# The material of eroded terrains before the splat rules: replaced where found.
OLD_MATERIAL_NAMES = ("Fracterra Eroded Terrain",)
ROUGHNESS = 0.85  # dry ground: a broad, faint highlight


# --- in the main thread, before the job

def rules_of(values):
    """The splat rules of a terrain's settings: its Material Rules file (blank:
    the library's built-in set), read and checked by the library. A bad file
    is a SettingsError with the library's message (file, layer and field)."""
    path = values.get("splat_rules", "")
    if not path:
        return splat.default_rules()
    path = bpy.path.abspath(path)
    if not os.path.isfile(path):
        raise SettingsError(f"Material Rules: no file '{path}' (leave it blank for the built-in grass, rock, sediment "
                            "and snow)")
    try:
        return splat.read_rules(path)
    except core.FracterraError as e:
        raise SettingsError(f"Material Rules: {e}") from e


# --- in the job's worker thread (no bpy here)

def linear_colors(hf, rules, maps=None, threads=0, progress=None):
    """Linear RGBA per sample of library heightfield `hf` (float32, 4 per
    sample, rows as in hf) by `rules`, decoded by the library
    (core.splat.linear_rgba); maps: the pipeline's erosion maps ({name:
    array.array('f')} in world units) or None (uneroded: the deposit and flow
    conditions see none). progress: None or callable(fraction) -> True to
    cancel (raises CancelledError)."""
    extra = {}
    try:
        for name in ("deposited", "drainage_area"):
            if maps is not None and name in maps:
                extra[name] = core.Heightfield.from_values(hf.width, hf.height, maps[name])
        return splat.linear_rgba(hf, rules, extra.get("deposited"), extra.get("drainage_area"), threads=threads,
                                 progress=progress)
    finally:
        for m in extra.values():
            m.close()


# --- in the main thread (build steps)

def set_colors(mesh, rgba):
    """Writes the colour attribute (rgba: linear, 4 per vertex) and gives a mesh
    without a material (or with the old eroded one) the terrain material."""
    layer = mesh.attributes.get(COLOR_ATTRIBUTE)
    if layer is not None and (layer.domain != "POINT" or layer.data_type != "FLOAT_COLOR"):
        mesh.attributes.remove(layer)
        layer = None
    if layer is None:
        layer = mesh.attributes.new(COLOR_ATTRIBUTE, "FLOAT_COLOR", "POINT")
        huge_pages.advise(layer.data)
    layer.data.foreach_set("color", rgba)
    # The viewport's Attribute colour (Solid mode) shows it too.
    colors = getattr(mesh, "color_attributes", None)
    if colors is not None and colors.get(COLOR_ATTRIBUTE) is not None:
        colors.active_color = colors[COLOR_ATTRIBUTE]
        if hasattr(colors, "render_color_index"):
            colors.render_color_index = colors.active_color_index
    give_material(mesh)


def give_material(mesh):
    """The terrain material for a mesh without one (or with the old eroded one)."""
    if len(mesh.materials) == 0:
        mesh.materials.append(terrain_material())
    elif mesh.materials[0] is not None and mesh.materials[0].name.split(".")[0] in OLD_MATERIAL_NAMES:
        mesh.materials[0] = terrain_material()


def terrain_material():
    """The node material of terrains (made once per file): the Base Color is
    the colour attribute, so the material shows exactly the library's colour
    map by the terrain's rules."""
    mat = bpy.data.materials.get(MATERIAL_NAME)
    if mat is not None:
        return mat
    mat = bpy.data.materials.new(MATERIAL_NAME)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes.get("Principled BSDF")
    bsdf.inputs["Roughness"].default_value = ROUGHNESS
    node = nodes.new("ShaderNodeAttribute")
    node.attribute_type = "GEOMETRY"
    node.attribute_name = COLOR_ATTRIBUTE
    node.location = (-400, 200)
    links.new(node.outputs["Color"], bsdf.inputs["Base Color"])
    return mat


def is_terrain_material(material):
    return material is not None and material.name.split(".")[0] == MATERIAL_NAME


def attribute_colors(mesh):
    """The colour attribute as linear RGB (float32, 3 per vertex), or None."""
    layer = mesh.attributes.get(COLOR_ATTRIBUTE)
    if layer is None or layer.domain != "POINT" or layer.data_type != "FLOAT_COLOR":
        return None
    rgba = np.empty(4 * len(mesh.vertices), dtype=np.float32)
    layer.data.foreach_get("color", rgba)
    return np.ascontiguousarray(rgba.reshape(-1, 4)[:, :3]).ravel()
