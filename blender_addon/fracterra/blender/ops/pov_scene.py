# SPDX-License-Identifier: GPL-3.0-or-later
"""What the POV-Ray export reads from a Blender scene, in the library's terms
(core/povray.py): the lights in Blender's own units, the world's colour, the
materials of curves and meshes, the meshes and the rivers, all in the
writer's frame (frame @ world + shift, where the terrain spans 0..size).
The library converts them to POV-Ray by the rules of docs/povray.md."""

import math

import bpy
import numpy as np
from mathutils import Vector

from ... import core
from ...core.subdiv import Mesh
from ..build.objects import is_terrain
from ..build.water import KINDS as WATER_KINDS, MATERIAL_NAME as WATER_MATERIAL

# Cycles shades a surface without a material with a grey diffuse of this albedo.
DEFAULT_GREY = (0.8, 0.8, 0.8)
# Cycles before Blender 4.0 multiplies a spot light by the cosine from its
# axis inside the cone (measured: docs/povray.md, "Lights").
SPOT_COS_POWER = 1.0 if bpy.app.version < (4, 0, 0) else 0.0
# The flux an area light of Power 1 W emits: Cycles before 4.0 gives it the
# radiance P / (4 A), so pi / 4 W; from 4.0 on, 1 W (measured: docs/povray.md).
AREA_FLUX_PER_WATT = math.pi / 4 if bpy.app.version < (4, 0, 0) else 1.0


def _input(node, *names):
    """The first of a node's inputs named in `names` (Blender renames some: 'Specular' in 3.x is
    'Specular IOR Level' in 4.x), or None."""
    return next((node.inputs[n] for n in names if n in node.inputs), None)


def _unlinked(socket, default):
    """A socket's own value when nothing drives it, else `default`."""
    if socket is None or socket.is_linked:
        return default
    return socket.default_value


def _output_shader(material):
    """The shader node feeding the material's active output, or None."""
    if material is None or not material.use_nodes or material.node_tree is None:
        return None
    out = next((n for n in material.node_tree.nodes if n.type == "OUTPUT_MATERIAL" and n.is_active_output), None)
    if out is None or not out.inputs["Surface"].is_linked:
        return None
    return out.inputs["Surface"].links[0].from_node


def material_of(material, water=False):
    """{'color', 'emission', 'roughness', 'specular', 'water'} of a Blender material as Cycles
    shades it: a Principled BSDF's base colour, roughness, specular and emission (colour times
    strength), an Emission shader's colour times strength, a Diffuse BSDF's colour; a driven
    input falls back to the material's viewport colour; no material: Cycles' grey."""
    m = {"color": DEFAULT_GREY, "emission": (0.0, 0.0, 0.0), "roughness": 0.5, "specular": 0.5, "water": water}
    if material is None:
        return m
    m["color"] = tuple(material.diffuse_color[:3])
    m["roughness"] = material.roughness
    node = _output_shader(material)
    if node is None:
        return m
    if node.type == "BSDF_PRINCIPLED":
        m["color"] = tuple(_unlinked(node.inputs["Base Color"], material.diffuse_color)[:3])
        m["roughness"] = _unlinked(node.inputs["Roughness"], m["roughness"])
        m["specular"] = min(1.0, _unlinked(_input(node, "Specular", "Specular IOR Level"), 0.5))
        emission = _unlinked(_input(node, "Emission", "Emission Color"), (0, 0, 0, 1))
        strength = _unlinked(_input(node, "Emission Strength"), 1.0)
        m["emission"] = tuple(c * strength for c in emission[:3])
    elif node.type == "EMISSION":
        color = _unlinked(node.inputs["Color"], (1, 1, 1, 1))
        strength = _unlinked(node.inputs["Strength"], 1.0)
        m["color"], m["emission"] = (0.0, 0.0, 0.0), tuple(c * strength for c in color[:3])
    elif node.type == "BSDF_DIFFUSE":
        m["color"] = tuple(_unlinked(node.inputs["Color"], material.diffuse_color)[:3])
        m["roughness"], m["specular"] = 1.0, 0.0
    return m


def object_material(obj):
    """The first material of an object's slots, or None."""
    return next((slot.material for slot in obj.material_slots if slot.material is not None), None)


def is_water(obj):
    """A terrain's water object, or any object in the add-on's water material."""
    material = object_material(obj)
    return obj.get("fracterra_kind") in WATER_KINDS or (
        material is not None and material.name.split(".")[0] == WATER_MATERIAL)


def world_sky(scene):
    """The world's colour times strength (its Background node's, or the world colour when nodes
    drive it), linear RGB: the POV-Ray scene's background and ambient light."""
    world = scene.world
    if world is None:
        return (0.0, 0.0, 0.0)
    sky = tuple(world.color)
    background = world.node_tree.nodes.get("Background") if world.use_nodes and world.node_tree else None
    if background is not None and not background.inputs["Color"].is_linked:
        strength = _unlinked(background.inputs["Strength"], 1.0)
        sky = tuple(c * strength for c in background.inputs["Color"].default_value[:3])
    return sky


def _light_emission(data):
    """The colour times strength of a light's Cycles emission node (1, 1, 1 without one)."""
    if not data.use_nodes or data.node_tree is None:
        return (1.0, 1.0, 1.0)
    node = next((n for n in data.node_tree.nodes if n.type == "EMISSION"), None)
    if node is None:
        return (1.0, 1.0, 1.0)
    color = _unlinked(node.inputs["Color"], (1, 1, 1, 1))
    strength = _unlinked(node.inputs["Strength"], 1.0)
    return tuple(c * strength for c in color[:3])


def frame_scale(frame):
    """The writer's frame's length scale (the cube root of its volume scale)."""
    return abs(frame.to_3x3().determinant()) ** (1.0 / 3.0)


def light_of(obj, frame, shift):
    """One Blender light as a core.povray light dict in the writer's frame. Powers are Blender's
    (W, or W/m^2 for a sun); a point, spot or area light's power is scaled by the frame's scale
    squared, as distances in the frame are (the inverse square law holds there)."""
    data = obj.data
    world = obj.matrix_world
    to_frame = frame.to_3x3()
    emission = _light_emission(data)
    light = {"kind": data.type, "color": tuple(c * e for c, e in zip(data.color, emission)),
             "power": data.energy, "shadows": _casts_shadow(data),
             "location": tuple(frame @ world.translation + shift),
             "direction": tuple((to_frame @ (world.to_3x3() @ Vector((0.0, 0.0, -1.0)))).normalized())}
    if data.type != "SUN":
        light["power"] = data.energy * frame_scale(frame) ** 2
    if data.type == "SPOT":
        light["spot_size_deg"] = min(180.0, max(1.0, math.degrees(data.spot_size)))
        light["spot_blend"] = data.spot_blend
        light["spot_cos_power"] = SPOT_COS_POWER
    if data.type == "AREA":
        light["power"] *= AREA_FLUX_PER_WATT
        size_y = data.size_y if data.shape in ("RECTANGLE", "ELLIPSE") else data.size
        light["area_u"] = tuple(to_frame @ (world.to_3x3() @ Vector((data.size, 0.0, 0.0))))
        light["area_v"] = tuple(to_frame @ (world.to_3x3() @ Vector((0.0, size_y, 0.0))))
        light["area_ellipse"] = data.shape in ("DISK", "ELLIPSE")
    return light


def _casts_shadow(data):
    if hasattr(data, "use_shadow"):
        shadow = data.use_shadow
        cycles = getattr(data, "cycles", None)
        return bool(shadow and getattr(cycles, "cast_shadow", True))
    return True


def scene_lights(objects, frame, shift):
    """Every visible light of a type POV-Ray has (sun, point, spot, area) with some power."""
    return [light_of(o, frame, shift) for o in objects
            if o.type == "LIGHT" and o.data.type in ("SUN", "POINT", "SPOT", "AREA") and o.data.energy > 0]


def mesh_arrays(obj, depsgraph, matrix, shift):
    """(positions float32 xyz, face sizes, face indices, smooth) of an object's evaluated mesh
    (modifiers applied) mapped by `matrix` then moved by `shift`; None without faces."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        if len(mesh.polygons) == 0:
            return None
        co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        m = np.array(matrix, dtype=np.float64)
        xyz = co.reshape(-1, 3).astype(np.float64) @ m[:3, :3].T + m[:3, 3] + np.asarray(shift, dtype=np.float64)
        sizes = np.empty(len(mesh.polygons), dtype=np.int32)
        mesh.polygons.foreach_get("loop_total", sizes)
        indices = np.empty(len(mesh.loops), dtype=np.int32)
        mesh.loops.foreach_get("vertex_index", indices)
        smooth = np.empty(len(mesh.polygons), dtype=bool)
        mesh.polygons.foreach_get("use_smooth", smooth)
        return np.ascontiguousarray(xyz, dtype=np.float32).ravel(), sizes, indices, bool(smooth.any())
    finally:
        evaluated.to_mesh_clear()


def scene_meshes(objects, terrain, depsgraph, frame, shift):
    """(core.Mesh, material dict, smooth) of every visible mesh but the terrains (the terrain is
    the height_field), and the names of those the library refused (with its reason)."""
    meshes, skipped = [], []
    for obj in objects:
        if obj.type != "MESH" or obj is terrain or is_terrain(obj):
            continue
        arrays = mesh_arrays(obj, depsgraph, frame @ obj.matrix_world, shift)
        if arrays is None:
            continue
        positions, sizes, indices, smooth = arrays
        try:
            mesh = Mesh.create(positions, sizes, indices)
        except core.FracterraError as e:
            skipped.append(f"{obj.name} ({e})")
            continue
        meshes.append((mesh, material_of(object_material(obj), water=is_water(obj)), smooth))
    return meshes, skipped
