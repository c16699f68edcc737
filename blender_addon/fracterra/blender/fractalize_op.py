"""Object > Fractalize: OpenSubdiv refinement with fractal displacements."""

import array
import itertools

import bpy

from .. import core
from ..core import subdiv
from .terrain_build import SettingsError, WindowProgress

REPORTED = (core.FracterraError, SettingsError)


def _edge_creases(mesh):
    """(pairs, sharpness) from Blender's edge creases c in [0, 1] -> 10 c^2, as Blender's own subdivision."""
    n = len(mesh.edges)
    crease = array.array("f", [0.0]) * n
    try:
        mesh.edges.foreach_get("crease", crease)
    except (AttributeError, TypeError, RuntimeError):  # Blender 4.0+: an attribute
        layer = mesh.attributes.get("crease_edge")
        if layer is None:
            return None, None
        layer.data.foreach_get("value", crease)
    verts = array.array("I", [0]) * (2 * n)
    mesh.edges.foreach_get("vertices", verts)
    pairs, sharp = array.array("I"), array.array("f")
    for i, c in enumerate(crease):
        if c > 0:
            pairs.extend(verts[2 * i:2 * i + 2])
            sharp.append(10.0 * c * c)
    return (pairs, sharp) if sharp else (None, None)


def ft_mesh_of(mesh, use_creases):
    co = array.array("f", [0.0]) * (3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    sizes = array.array("I", [0]) * len(mesh.polygons)
    mesh.polygons.foreach_get("loop_total", sizes)
    indices = array.array("I", [0]) * len(mesh.loops)
    mesh.loops.foreach_get("vertex_index", indices)
    if not sizes:
        raise SettingsError(f"'{mesh.name}' has no faces to fractalize")
    pairs, sharp = _edge_creases(mesh) if use_creases else (None, None)
    return subdiv.Mesh.create(co, sizes, indices, pairs, sharp)


def fill_polygon_mesh(mesh, positions, sizes, indices):
    mesh.clear_geometry()
    mesh.vertices.add(len(positions) // 3)
    mesh.loops.add(len(indices))
    mesh.polygons.add(len(sizes))
    mesh.vertices.foreach_set("co", positions)
    mesh.loops.foreach_set("vertex_index", indices)
    starts = array.array("I", itertools.accumulate(itertools.chain((0,), sizes[:-1])))
    mesh.polygons.foreach_set("loop_start", starts)
    if not bpy.types.MeshPolygon.bl_rna.properties["loop_total"].is_readonly:
        mesh.polygons.foreach_set("loop_total", sizes)
    mesh.update(calc_edges=True)


class FRACTERRA_OT_fractalize(bpy.types.Operator):
    """Subdivide the active mesh with fractal (midpoint or additions) displacements, using OpenSubdiv"""
    bl_idname = "object.fracterra_fractalize"
    bl_label = "Fractalize"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    levels: bpy.props.IntProperty(name="Levels", default=3, min=1, max=10, soft_max=6,
                                  description="Refinement steps: faces grow 4^levels")
    hurst: bpy.props.FloatProperty(name="Hurst H", default=0.8, min=0.0, max=1.0, subtype="FACTOR",
                                   description="Hurst exponent: level k moves by sigma 2^(-kH)")
    sigma: bpy.props.FloatProperty(name="Sigma", default=0.1, min=0.0, soft_max=10.0, subtype="DISTANCE",
                                   unit="LENGTH", description="Displacement scale (0: plain subdivision)")
    seed: bpy.props.IntProperty(name="Seed", default=1, min=0, max=2**31 - 1, description="Random seed")
    scheme: bpy.props.EnumProperty(name="Scheme", default="CATMARK", items=[
        ("CATMARK", "Catmull-Clark", "Any polygons in, quads out", 0),
        ("LOOP", "Loop", "Triangles in (only), triangles out", 1),
        ("BILINEAR", "Bilinear", "Any polygons in, quads out, no smoothing", 2)])
    mode: bpy.props.EnumProperty(name="Mode", default="VOSS", items=[
        ("VOSS", "Midpoint", "Only the vertices new at each level move", 0),
        ("ADDITIONS", "Additions", "Feder's successive random additions: every vertex moves", 1)])
    fix_boundary: bpy.props.BoolProperty(name="Fix Boundary", default=False,
                                         description="Vertices on open edges never move")
    scale_by_edge_length: bpy.props.BoolProperty(
        name="Relative Sigma", default=False, description="Sigma is a fraction of the local edge length")
    use_creases: bpy.props.BoolProperty(name="Edge Creases", default=True,
                                        description="Honour the mesh's edge creases")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and context.mode == "OBJECT"

    def execute(self, context):
        obj = context.active_object
        try:
            with ft_mesh_of(obj.data, self.use_creases) as base, WindowProgress(context) as progress, \
                    subdiv.fractalize(base, self.levels, self.hurst, self.sigma, self.seed, self.scheme, self.mode,
                                      self.fix_boundary, self.scale_by_edge_length, progress=progress) as out:
                positions, sizes, indices = out.positions(), out.face_sizes(), out.face_indices()
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        mesh = bpy.data.meshes.new(obj.data.name + " Fractal")
        fill_polygon_mesh(mesh, positions, sizes, indices)
        for mat in obj.data.materials:
            mesh.materials.append(mat)
        old = obj.data
        obj.data = mesh
        if old.users == 0:
            bpy.data.meshes.remove(old)
        self.report({"INFO"}, f"Fractalized: {len(sizes)} faces")
        return {"FINISHED"}


def menu_object(self, context):
    self.layout.operator(FRACTERRA_OT_fractalize.bl_idname, icon="MOD_DISPLACE")
