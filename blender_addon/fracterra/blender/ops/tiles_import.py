# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Import > fracterra tile set: a window of a tile set (fracterra tiles,
docs/scale.md) at a level of detail, as one mesh or as one object per tile.

The samples are read back from the tile files by the library
(ft_tileset_read_window): every 2^lod-th sample of the whole, which for a
midpoint terrain is exactly its coarser stage. The set's row 0 is its north
edge; meshes are built north up (+y), in the set's world units (or scaled to
Size), centred on the window; per-tile objects share their edge vertices with
their neighbours, so they meet without cracks.

Shading: Blender's smooth normals of a separate object see only its own
faces, so at a shared edge the two tiles' normals differ and a seam line shows
under a low light (rendered in docs/scale.md). Every vertex therefore gets a
custom normal from the central differences of the set's samples around it,
read with a margin of one sample beyond the piece: the same normal on both
sides of a tile edge, and the same in one mesh as in per-tile objects."""

import array
import os
import time

import bpy
import numpy as np
from bpy_extras.io_utils import ImportHelper

from ... import core
from ...core import mesh_limits
from ...core import tiles as core_tiles
from ...core.grid import grid_arrays
from ..build import mesh as mesh_build
from ..build import splat_material
from ..common.reporting import REPORTED, SettingsError


def _north_up(values, world_size, north_up=True):
    """A new core.Heightfield (caller closes) of `values` (rows from the north) with its rows
    reversed (north up), or as they are (row 0 at -y, as the add-on's terrain objects lie)."""
    h, w = values.shape
    rows = values[::-1] if north_up else values
    flipped = core.Heightfield.from_values(w, h, array.array("f", rows.astype(np.float32).tobytes()))
    flipped._lib.ft_heightfield_set_world_size(flipped.handle, world_size)
    return flipped


def _read_with_margin(folder, lod, x, y, w, h, ew, eh):
    """(samples of the window, rows from the north, as a (h + top + bottom, w + left + right)
    array, (left, top)): the window grown by one sample on each side where the set has one."""
    mx0, my0 = max(0, x - 1), max(0, y - 1)
    mx1, my1 = min(ew, x + w + 1), min(eh, y + h + 1)
    with core_tiles.read_window(folder, lod, mx0, my0, mx1 - mx0, my1 - my0) as hf:
        values = np.array(hf.to_array(), dtype=np.float64).reshape(my1 - my0, mx1 - mx0)
    return values, (x - mx0, y - my0)


def _normals(margin, offset, w, h, step_x, step_y, north_up=True):
    """Unit normals (w h x 3, vertex order of the north-up mesh) of the window at `offset` in
    `margin`, whose z is already scaled: central differences of the set's samples (one-sided
    only at the set's own borders); step_x, step_y: scene units per column east and per row
    north."""
    g_rows, g_cols = np.gradient(margin)  # per row (southwards) and per column (eastwards)
    ox, oy = offset
    dzdx = g_cols[oy:oy + h, ox:ox + w] / step_x
    dzdy = (-1.0 if north_up else 1.0) * g_rows[oy:oy + h, ox:ox + w] / step_y
    n = np.dstack((-dzdx, -dzdy, np.ones_like(dzdx)))
    n = n[::-1] if north_up else n
    n /= np.linalg.norm(n, axis=2, keepdims=True)
    return n.reshape(-1, 3).astype(np.float32)


def _set_normals(mesh, normals):
    """Custom per-vertex normals (Blender 3.x needs auto smooth for them to show)."""
    if hasattr(mesh, "use_auto_smooth"):
        mesh.use_auto_smooth = True
        mesh.auto_smooth_angle = 3.14159
    mesh.normals_split_custom_set_from_vertices(normals)


def _pieces(m, lod, x0, y0, w, h, per_tile):
    """[(a, b, pw, ph)] windows (lod samples, relative to the window) to build: the whole window,
    or each tile's share of it (neighbours share their edge samples)."""
    if not per_tile:
        return [(0, 0, w, h)]
    step = 2 ** lod
    out = []
    for e in m["tiles"]:
        # The tile's samples at this lod: [ceil(tx0 / step), floor((tx0 + tw - 1) / step)].
        lo_x, hi_x = -(-e["x0"] // step), (e["x0"] + e["width"] - 1) // step
        lo_y, hi_y = -(-e["y0"] // step), (e["y0"] + e["height"] - 1) // step
        a0, a1 = max(lo_x, x0), min(hi_x, x0 + w - 1)
        b0, b1 = max(lo_y, y0), min(hi_y, y0 + h - 1)
        if a1 - a0 >= 1 and b1 - b0 >= 1:  # at least 2 x 2 samples make a mesh
            out.append((a0 - x0, b0 - y0, a1 - a0 + 1, b1 - b0 + 1))
    return out


class FRACTERRA_OT_import_tiles(bpy.types.Operator, ImportHelper):
    """Import a window of a fracterra tile set (its manifest.json) at a level of detail, as one mesh or one object per tile"""
    bl_idname = "import_scene.fracterra_tiles"
    bl_label = "Import Tile Set"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filename_ext = ".json"
    filter_glob: bpy.props.StringProperty(default="manifest.json", options={"HIDDEN"})
    lod: bpy.props.IntProperty(
        name="Level of Detail", default=0, min=0, max=24,
        description="Every 2^lod-th sample of the set (for midpoint terrains exactly the coarser stage)")
    x0: bpy.props.IntProperty(name="Window X", default=0, min=0,
                              description="First column of the window, in samples at this level of detail")
    y0: bpy.props.IntProperty(name="Window Y", default=0, min=0,
                              description="First row (from the north edge), in samples at this level of detail")
    width: bpy.props.IntProperty(name="Window Width", default=0, min=0,
                                 description="Samples across at this level of detail (0: to the east edge)")
    height: bpy.props.IntProperty(name="Window Height", default=0, min=0,
                                  description="Samples down at this level of detail (0: to the south edge)")
    mode: bpy.props.EnumProperty(
        name="Import As", default="MESH",
        items=[("MESH", "One Mesh", "The window as one mesh"),
               ("TILES", "Object per Tile", "One object per tile the window touches, edge to edge")])
    size: bpy.props.FloatProperty(
        name="Size", default=0.0, min=0.0, subtype="DISTANCE",
        description="Extent of the window along x in scene units, heights scaled alike (0: the set's own units)")
    north_up: bpy.props.BoolProperty(
        name="North Up", default=True,
        description="The set's first row (its north edge) towards +y, as maps are drawn; off: towards -y, as "
                    "the add-on's terrain objects lie (Build Tile Set imports so, beside its object)")
    splat_rules: bpy.props.StringProperty(
        name="Splat Rules", default="", subtype="FILE_PATH",
        description="The colours' rules file (fracterra splat --print-rules); blank: the built-in grass, rock, "
                    "sediment and snow")

    def execute(self, context):
        try:
            message = self.import_tiles(context)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}

    def import_tiles(self, context):
        t0 = time.perf_counter()
        folder = os.path.dirname(self.filepath) if self.filepath.endswith(".json") else self.filepath
        m = core_tiles.manifest(folder)
        ew, eh = core_tiles.extent(folder, self.lod)
        w = self.width or ew - self.x0
        h = self.height or eh - self.y0
        if w < 2 or h < 2 or self.x0 + w > ew or self.y0 + h > eh:
            raise SettingsError(f"Import tile set: the window ({self.x0}, {self.y0}) + {w} x {h} is not inside the "
                                f"set's {ew} x {eh} samples at level of detail {self.lod} (at least 2 x 2)")
        mesh_limits.check_grid(w, h)
        rules = splat_material.rules_of({"splat_rules": self.splat_rules})
        spacing = m["sample_spacing"] * 2 ** self.lod
        scale = self.size / (spacing * (w - 1)) if self.size > 0 else 1.0
        collection = bpy.data.collections.new(os.path.basename(os.path.normpath(folder)) or "tiles")
        context.scene.collection.children.link(collection)
        last = None
        pieces = _pieces(m, self.lod, self.x0, self.y0, w, h, self.mode == "TILES")
        for a, b, pw, ph in pieces:
            margin, (ox, oy) = _read_with_margin(folder, self.lod, self.x0 + a, self.y0 + b, pw, ph, ew, eh)
            world = spacing * (pw - 1)
            with _north_up(margin[oy:oy + ph, ox:ox + pw], world, self.north_up) as flipped:
                g = grid_arrays(flipped, world)
            if scale != 1.0:
                g.co = array.array("f", (np.frombuffer(g.co, dtype=np.float32) * scale).tobytes())
            normals = _normals(margin * scale, (ox, oy), pw, ph, spacing * scale, spacing * scale, self.north_up)
            colors = core_tiles.window_colors(folder, rules, self.lod, self.x0 + a, self.y0 + b, pw, ph)
            colors = colors.reshape(ph, pw, 4)
            colors = np.ascontiguousarray(colors[::-1] if self.north_up else colors).ravel()  # as the mesh
            name = f"{collection.name} r{self.y0 + b} c{self.x0 + a}" if len(pieces) > 1 else collection.name
            mesh = bpy.data.meshes.new(name)
            try:
                mesh_build.fill_grid_mesh(mesh, g, smooth=True)
                _set_normals(mesh, normals)
                splat_material.set_colors(mesh, colors)
            except BaseException:
                bpy.data.meshes.remove(mesh)
                raise
            obj = bpy.data.objects.new(name, mesh)
            # Meshes are centred on their own middle: place each at its middle's offset from the
            # window's (north up: rows go towards -y).
            middle_y = (h - 1) / 2 - (b + (ph - 1) / 2)
            obj.location = (scale * spacing * (a + (pw - 1) / 2 - (w - 1) / 2),
                            scale * spacing * (middle_y if self.north_up else -middle_y), 0.0)
            collection.objects.link(obj)
            last = obj
        if last is not None:
            context.view_layer.objects.active = last
        return (f"{w} x {h} samples of the tile set at level of detail {self.lod} as {len(pieces)} "
                f"object{'s' if len(pieces) != 1 else ''} in {time.perf_counter() - t0:.2f} s")
