# SPDX-License-Identifier: GPL-3.0-or-later
"""Object > Fractalize: OpenSubdiv refinement with fractal displacements."""

import bpy
import numpy as np

from ...core import params, subdiv
from ..ui import properties as props
from ..build.mesh import set_smooth
from ..common.preferences import library_threads
from ..common.jobs import Job, JobOperator
from ..common.reporting import SettingsError


def _edge_creases(mesh):
    """(pairs, sharpness) from Blender's edge creases c in [0, 1] -> 10 c^2, as Blender's own
    subdivision; (None, None) when no edge is creased."""
    n = len(mesh.edges)
    crease = np.zeros(n, dtype=np.float32)
    try:
        mesh.edges.foreach_get("crease", crease)
    except (AttributeError, TypeError, RuntimeError):  # Blender 4.0+: an attribute
        layer = mesh.attributes.get("crease_edge")
        if layer is None:
            return None, None
        layer.data.foreach_get("value", crease)
    creased = np.flatnonzero(crease > 0)
    if not len(creased):
        return None, None
    verts = np.empty(2 * n, dtype=np.uint32)
    mesh.edges.foreach_get("vertices", verts)
    pairs = verts.reshape(n, 2)[creased].ravel()
    return pairs, 10.0 * crease[creased] ** 2


def ft_mesh_of(mesh, use_creases):
    """A core subdiv.Mesh of a Blender mesh's vertices, faces and (optionally) creases."""
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    sizes = np.empty(len(mesh.polygons), dtype=np.uint32)
    mesh.polygons.foreach_get("loop_total", sizes)
    indices = np.empty(len(mesh.loops), dtype=np.uint32)
    mesh.loops.foreach_get("vertex_index", indices)
    if not len(sizes):
        raise SettingsError(f"'{mesh.name}' has no faces to fractalize")
    pairs, sharp = _edge_creases(mesh) if use_creases else (None, None)
    return subdiv.Mesh.create(co, sizes, indices, pairs, sharp)


def fill_polygon_mesh(mesh, positions, sizes, indices):
    """Replaces the geometry of `mesh` by the polygons the library made."""
    sizes = np.asarray(sizes, dtype=np.uint32)
    mesh.clear_geometry()
    mesh.vertices.add(len(positions) // 3)
    mesh.loops.add(len(indices))
    mesh.polygons.add(len(sizes))
    mesh.vertices.foreach_set("co", positions)
    mesh.loops.foreach_set("vertex_index", indices)
    starts = np.zeros(len(sizes), dtype=np.uint32)
    np.cumsum(sizes[:-1], out=starts[1:])
    mesh.polygons.foreach_set("loop_start", starts)
    if not bpy.types.MeshPolygon.bl_rna.properties["loop_total"].is_readonly:
        mesh.polygons.foreach_set("loop_total", sizes)
    mesh.update(calc_edges=True)


def _fractalized_mesh(name, result, smooth, materials):
    """Build steps of the new mesh (one step: filling it is a few array copies);
    removed again if cancelled or failed."""
    positions, sizes, indices = result
    mesh = bpy.data.meshes.new(name)
    try:
        fill_polygon_mesh(mesh, positions, sizes, indices)
        set_smooth(mesh, smooth)
        for mat in materials:
            mesh.materials.append(mat)
        yield 1.0
    except BaseException:  # GeneratorExit too: a cancel leaves no mesh behind
        bpy.data.meshes.remove(mesh)
        raise
    return mesh, len(sizes)


class FRACTERRA_OT_fractalize(JobOperator, bpy.types.Operator):
    """Subdivide the active mesh with fractal (midpoint or additions) displacements, using OpenSubdiv"""
    bl_idname = "object.fracterra_fractalize"
    bl_label = "Fractalize"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and context.mode == "OBJECT"

    # From the menu it runs in the background with a progress bar (Esc cancels):
    # OpenSubdiv's refinement in the worker thread, the mesh swapped in at the
    # end, so a cancel leaves the object as it was.
    def make_job(self, context):
        obj = self._obj = context.active_object
        base = ft_mesh_of(obj.data, self.use_creases)  # read here (it needs bpy); freed by the work
        settings = (self.levels, self.hurst, self.sigma, self.seed, self.scheme, self.mode, self.fix_boundary,
                    self.scale_by_edge_length)
        threads = library_threads(context)

        def work(progress):
            with base, subdiv.fractalize(base, *settings, threads=threads, progress=progress) as out:
                return out.positions(), out.face_sizes(), out.face_indices()

        name, smooth, materials = obj.data.name + " Fractal", self.smooth, list(obj.data.materials)
        return Job("Fractalizing", work, lambda result: _fractalized_mesh(name, result, smooth, materials),
                   work_share=0.9)

    def job_done(self, context, value):
        mesh, faces = value
        obj = self._obj
        old = obj.data
        obj.data = mesh
        if old.users == 0:
            bpy.data.meshes.remove(old)
        self.report({"INFO"}, f"Fractalized: {faces} faces in {self.job_seconds:.2f} s")
        return {"FINISHED"}


# Its properties: the library's description of ft_fractalize_params (labels,
# tooltips, ranges, defaults; Blender's differences stated in core/params.py),
# then Edge Creases and Smooth Shading, which are Blender's own.
FRACTERRA_OT_fractalize.__annotations__ = props.terrain_annotations(param_list=params.FRACTALIZE_PARAMS)

