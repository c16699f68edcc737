# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Import > DEM as terrain, and File > Export > terrain heights, in
every format the library reads and writes (fracterra/raster.h, docs/gis.md).

A map's first row is its north edge; a terrain mesh has row 0 at y = 0 (its
south edge). Import flips the rows so north is +y, and export flips them
back, so a DEM imported and exported keeps its orientation."""

import array
import time

import bpy
import numpy as np
from bpy_extras.io_utils import ExportHelper, ImportHelper

from ... import core
from ...core import raster
from ...core.grid import grid_arrays
from ..build import mesh as mesh_build
from ..common.reporting import REPORTED, SettingsError
from ..build.objects import heightfield_of, is_terrain


def _flipped(hf, world_size, scale=1.0):
    """A new core.Heightfield (caller closes): the rows of `hf` in reverse
    order, heights times `scale`, world size `world_size` times `scale`."""
    w, h = hf.width, hf.height
    rows = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(h, w)[::-1] * np.float32(scale)
    values = array.array("f")
    values.frombytes(np.ascontiguousarray(rows, dtype=np.float32).tobytes())
    flipped = core.Heightfield.from_values(w, h, values)
    flipped._lib.ft_heightfield_set_world_size(flipped.handle, world_size * scale)
    return flipped


class FRACTERRA_OT_import_dem(bpy.types.Operator, ImportHelper):
    """Import a DEM (GeoTIFF, .hgt, ASCII grid, EXR, RAW16, ...) as a terrain mesh, optionally refined"""
    bl_idname = "import_scene.fracterra_dem"
    bl_label = "Import DEM"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filter_glob: bpy.props.StringProperty(
        default="*.tif;*.tiff;*.hgt;*.asc;*.vrt;*.dem;*.exr;*.raw;*.r16;*.png;*.pgm;*.npy", options={"HIDDEN"})
    nodata: bpy.props.EnumProperty(
        name="Nodata", default="FILL",
        items=[("FILL", "Fill", "Fill holes by GDAL's inverse-distance fill"),
               ("REFUSE", "Refuse", "Refuse a DEM with holes, naming their count")])
    refine_levels: bpy.props.IntProperty(
        name="Refine Levels", default=0, min=0, max=6,
        description="0: the DEM as it is; K: refine a (2^m + 1)^2 window of it by K midpoint levels, "
                    "its samples kept at their nodes, H and sigma measured on it")
    seed: bpy.props.IntProperty(name="Seed", default=1, min=0)
    size: bpy.props.FloatProperty(
        name="Size", default=10.0, min=0.0, subtype="DISTANCE",
        description="Extent along x in scene units, heights scaled alike (0: the DEM's own metres)")

    def execute(self, context):
        try:
            message = self.import_dem(context)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}

    def grid(self, hf):
        """The mesh arrays of `hf`, north up, scaled to `size`."""
        world = hf.world_size or float(hf.width - 1)
        scale = self.size / world if self.size > 0 else 1.0
        with _flipped(hf, world, scale) as flipped:
            return grid_arrays(flipped, flipped.world_size)

    def import_dem(self, context):
        t0 = time.perf_counter()
        # Refining picks a window without holes: they are kept, not filled.
        nodata = "KEEP" if self.refine_levels and self.nodata == "FILL" else self.nodata
        note = ""
        with raster.read_heightfield(self.filepath, nodata=nodata) as dem:
            if self.refine_levels:
                refined, report = raster.refine_dem(dem, levels_added=self.refine_levels, seed=self.seed)
                with refined:
                    g = self.grid(refined)
                note = f", refined +{self.refine_levels} with H {report['hurst']:.3f}"
            else:
                g = self.grid(dem)
        mesh = bpy.data.meshes.new(bpy.path.display_name_from_filepath(self.filepath))
        try:
            mesh_build.fill_grid_mesh(mesh, g, smooth=True)
        except BaseException:
            bpy.data.meshes.remove(mesh)
            raise
        obj = bpy.data.objects.new(mesh.name, mesh)
        context.collection.objects.link(obj)
        context.view_layer.objects.active = obj
        return f"{g.nx} x {g.ny} DEM terrain{note} in {time.perf_counter() - t0:.2f} s"


class FRACTERRA_OT_export_heights(bpy.types.Operator, ExportHelper):
    """Export the active fracterra terrain's heights (.tif COG, .exr, .raw/.r16, .png, .pgm, .npy)"""
    bl_idname = "export_scene.fracterra_heights"
    bl_label = "Export Heights"
    bl_options = {"REGISTER", "PRESET"}

    filename_ext = ".tif"
    filter_glob: bpy.props.StringProperty(default="*.tif;*.exr;*.raw;*.r16;*.png;*.pgm;*.npy", options={"HIDDEN"})
    check_extension = False  # every extension of raster.WRITE_EXTENSIONS is kept as typed

    def execute(self, context):
        try:
            obj = context.active_object
            if not is_terrain(obj):
                raise SettingsError("Export heights: make a fracterra terrain the active object")
            if not self.filepath.lower().endswith(raster.WRITE_EXTENSIONS):
                raise SettingsError(f"Export heights: use one of {', '.join(raster.WRITE_EXTENSIONS)}")
            with heightfield_of(obj) as hf:
                # The mesh's own extent along x (its vertices span the world size).
                world = obj.dimensions.x / obj.scale.x if obj.scale.x else float(hf.width - 1)
                with _flipped(hf, world) as out:
                    raster.write_heightfield(out, self.filepath)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"heights written to {self.filepath}")
        return {"FINISHED"}
