# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Export > Tile Set (fracterra), "Build Tile Set...": the active
terrain's own settings (what the sidebar shows and the mesh was built from:
method, landform, erosion preset, Strength, masks), written as a tile set
(docs/scale.md) Finer By levels finer: the same terrain in world units with
2^k times the samples per side, every tile a window of it bit-identical to
the whole (an eroded set has no seams), one tile at a time in the library.

It runs as a job (progress bar, Esc cancels; a cancelled or failed build
keeps what it wrote, and building into the same folder again resumes it).
Import Set then imports the finished set at the level of detail that has
the object's own number of samples, beside the object, with the splat
material. The add-on carries no Dask: larger sets go to the Python package's
driver (python3 -m fracterra.tiles) with the same settings."""

import os

import bpy
from bpy_extras.io_utils import ExportHelper
from mathutils import Matrix

from ... import core
from ...core import params
from ...core import tiles as core_tiles
from ..build import erosion_masks, falloff_mask
from ..build.objects import built_settings, is_terrain
from ..build.terrain import reference_for
from ..common.jobs import Job, JobOperator
from ..common.preferences import library_threads
from ..common.reporting import SettingsError


def finer_values(values, k):
    """The settings of the same terrain with 2^k times the cells per side (world size kept)."""
    finer = dict(values)
    if values["method"] in params._table("DYADIC_METHODS"):
        finer["levels"] = values["levels"] + k
    else:
        finer["width"] = (values["width"] - 1) * 2 ** k + 1
        finer["height"] = (values["height"] - 1) * 2 ** k + 1
    return finer


def recipe_of(obj, context, k):
    """(recipe, values) of terrain object `obj`'s settings k levels finer (core.tiles.recipe).
    Masks are read here, in the main thread, as for the terrain's own build."""
    values = built_settings(obj.data)
    if values is None:
        raise SettingsError(f"Build Tile Set: '{obj.name}' records no settings (regenerate it first)")
    reference = reference_for(values)
    mask = falloff_mask.mask_for(values, obj.matrix_world if obj else Matrix.Identity(4),
                                 context.evaluated_depsgraph_get(), obj.name)
    maps = erosion_masks.maps_for(values, obj)
    preset = values.get("erode_preset", "NONE")
    eroded = preset not in ("NONE", "CUSTOM") or (preset == "CUSTOM" and core.erosion.requested(values))
    finer = finer_values(values, k)
    r = core_tiles.recipe(finer, reference=reference, falloff_mask=mask,
                          erosion=values if eroded else None, preset="NONE" if preset == "CUSTOM" else preset,
                          maps=eroded, **(maps if eroded and maps else {}))
    return r, finer


def build_set(r, folder, tile, fmt, threads, progress):
    """Writes (or resumes) the set of recipe `r` in `folder`, tile by tile (the worker thread:
    no bpy). progress(fraction) -> True cancels between tiles. Returns a summary dict."""
    r = dict(r, settings=dict(r["settings"], threads=threads))
    ts, pending = core_tiles.TileSet.open_build(r, folder, tile, fmt)
    with ts:
        cols, rows = ts.grid()
        n = cols * rows
        tiles = [(c, row) for row in range(rows) for c in range(cols)]
        steps = (2 * n if pending else n) + 1
        done = 0
        if pending:  # the exact range pass, which keeps each eroded tile for the writing pass
            lo, hi = float("inf"), float("-inf")
            for c, row in tiles:
                if progress(done / steps):
                    raise core.CancelledError("Build Tile Set: cancelled", core.errors.FT_ERR_CANCELLED)
                a, b = core_tiles.built_tile_range(c, row, r, tile, fmt, os.path.abspath(folder))
                lo, hi = min(lo, a), max(hi, b)
                done += 1
            ts.set_height_range(lo, hi)
        lo, hi = ts.height_range()
        written = 0
        for c, row in tiles:
            if progress(done / steps):
                raise core.CancelledError("Build Tile Set: cancelled", core.errors.FT_ERR_CANCELLED)
            if not ts.done(c, row):
                ts.record_tile(*core_tiles.write_built_tile(c, row, r, tile, fmt, lo, hi, os.path.abspath(folder)))
                written += 1
            done += 1
        ts.finish()
        progress(1.0)
    return {"tiles": n, "written": written}


class FRACTERRA_OT_export_tiles(JobOperator, bpy.types.Operator, ExportHelper):
    """Build a tile set of the active terrain from its own settings, finer: the same terrain with more samples, every tile seamless (docs/scale.md)"""
    bl_idname = "export_scene.fracterra_tiles"
    bl_label = "Build Tile Set (fracterra)"
    bl_options = {"REGISTER"}

    filename_ext = ""
    use_filter_folder = True
    filter_glob: bpy.props.StringProperty(default="", options={"HIDDEN"})
    finer_by: bpy.props.IntProperty(
        name="Finer By", default=1, min=0, max=8,
        description="Levels finer than the object: 2^k times its samples per side, the same terrain in world units")
    tile: bpy.props.IntProperty(
        name="Tile", default=256, min=2, max=65536,
        description="Cells per tile side (tiles hold tile + 1 samples, neighbours share their edges); an eroded "
                    "set's tile must divide the terrain's cells")
    tile_format: bpy.props.EnumProperty(
        name="Format", default="png16",
        items=[("png16", "16-bit PNG", "One height scale for all tiles; what POV-Ray's height_field reads"),
               ("tiff", "Float GeoTIFF", "Exact float32 heights, georeferenced")])
    import_set: bpy.props.BoolProperty(
        name="Import Set", default=True,
        description="Import the finished set beside the object, at the level of detail of the object's samples")

    @classmethod
    def poll(cls, context):
        return context.mode == "OBJECT" and is_terrain(context.active_object)

    def _folder(self):
        path = bpy.path.abspath(self.filepath)
        return path if os.path.isdir(path) or not os.path.splitext(path)[1] else os.path.dirname(path)

    def make_job(self, context):
        obj = context.active_object
        if not is_terrain(obj):
            raise SettingsError("Build Tile Set: select a fracterra terrain")
        r, values = recipe_of(obj, context, self.finer_by)
        folder = self._folder()
        if not folder:
            raise SettingsError("Build Tile Set: choose the tile set's folder")
        threads = library_threads(context)
        self._object_name, self._folder_path = obj.name, folder
        return Job("Building tile set", lambda progress: build_set(r, folder, self.tile, self.tile_format, threads,
                                                                   progress))

    def job_done(self, context, summary):
        message = (f"Tile set in {self._folder_path}: {summary['tiles']} tiles ({summary['written']} written) "
                   f"in {self.job_seconds:.1f} s")
        if self.import_set:
            # In the set's own units and row order, which are the terrain mesh's: beside the object, one
            # width to the east.
            result = bpy.ops.import_scene.fracterra_tiles(filepath=os.path.join(self._folder_path, "manifest.json"),
                                                          lod=self.finer_by, north_up=False)
            if "FINISHED" not in result:
                return {"CANCELLED"}
            obj, imported = bpy.data.objects.get(self._object_name), context.view_layer.objects.active
            if obj is not None and imported is not None and imported is not obj:
                local_width = obj.dimensions.x / max(abs(obj.scale.x), 1e-12)
                imported.matrix_world = (obj.matrix_world @ Matrix.Translation((1.1 * local_width, 0.0, 0.0)) @
                                         imported.matrix_world)
        self.report({"INFO"}, message)
        return {"FINISHED"}
