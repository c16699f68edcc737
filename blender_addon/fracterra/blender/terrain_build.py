"""From settings to a terrain mesh: reference points, generation with
progress, building a new mesh or rewriting an existing one in place."""

import array
import math
import time

import bpy

from .. import core
from ..core import params
from ..core.grid import NO_FLOOR, grid_arrays, grid_size, vertices
from . import mesh_build


class SettingsError(ValueError):
    """A setting the add-on checks itself (reference object/image) is unusable."""


def _dyadic_levels(size):
    n = size - 1
    return n.bit_length() - 1 if size >= 3 and n & (n - 1) == 0 else -1


def reference_from_object(name):
    """(size, heights) from a mesh whose vertices form a (2^m + 1)^2 grid.

    Heights are local z; vertices are ordered by y, then x, so any grid
    (Add > Mesh > Grid, a fracterra terrain, an imported survey) works.
    """
    obj = bpy.data.objects.get(name) if name else None
    if obj is None or obj.type != "MESH":
        raise SettingsError(f"Reference: choose a mesh object for 'Grid Object' (got {name or 'nothing'!r})")
    mesh = obj.data
    n = len(mesh.vertices)
    size = math.isqrt(n)
    if size * size != n or _dyadic_levels(size) < 1:
        raise SettingsError(
            f"Reference object '{obj.name}' has {n} vertices; a reference grid needs (2^m + 1)^2 vertices "
            f"(9, 25, 81, 289, 1089, ...), e.g. Add > Mesh > Grid with 8 x 8 subdivisions (9 x 9 vertices)")
    co = array.array("f", [0.0]) * (3 * n)
    mesh.vertices.foreach_get("co", co)
    order = sorted(range(n), key=lambda i: (co[3 * i + 1], co[3 * i]))
    return size, [co[3 * i + 2] for i in order]


def reference_from_image(name, levels, height):
    """(size, heights): the image's luminance resampled bilinearly to (2^levels + 1)^2
    points; white is `height`. Image row 0 (the bottom) is y = 0, as in the terrain."""
    image = bpy.data.images.get(name) if name else None
    if image is None:
        raise SettingsError(f"Reference: choose an image for 'Image' (got {name or 'nothing'!r})")
    w, h = image.size
    if w < 1 or h < 1:
        raise SettingsError(f"Reference image '{image.name}' has no pixels (is the file missing?)")
    channels = image.channels
    px = array.array("f", [0.0]) * (w * h * channels)
    image.pixels.foreach_get(px)

    def lum(x, y):
        i = (y * w + x) * channels
        if channels >= 3:
            return 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2]
        return px[i]

    size = 2 ** levels + 1
    out = []
    for j in range(size):
        fy = j / (size - 1) * (h - 1)
        y0 = int(fy)
        y1, ty = min(y0 + 1, h - 1), fy - y0
        for i in range(size):
            fx = i / (size - 1) * (w - 1)
            x0 = int(fx)
            x1, tx = min(x0 + 1, w - 1), fx - x0
            top = lum(x0, y0) * (1 - tx) + lum(x1, y0) * tx
            bottom = lum(x0, y1) * (1 - tx) + lum(x1, y1) * tx
            out.append(height * (top * (1 - ty) + bottom * ty))
    return size, out


def reference_for(values):
    if values["method"] not in params.DYADIC_METHODS:
        return None
    source = values["reference_source"]
    if source == "OBJECT":
        return reference_from_object(values["reference_object"])
    if source == "IMAGE":
        return reference_from_image(values["reference_image"], values["reference_levels"],
                                    values["reference_height"])
    return None


def z_floor(values):
    return values["sea_level"] if values["use_sea_level"] else NO_FLOOR


class WindowProgress:
    """wm.progress_begin/update/end around a library call, as its progress callback."""

    def __init__(self, context):
        self.wm = getattr(context, "window_manager", None)

    def __enter__(self):
        if self.wm:
            self.wm.progress_begin(0, 1000)
        return self

    def __call__(self, fraction):
        if self.wm:
            self.wm.progress_update(int(fraction * 1000))
        return False  # never cancels on its own; the binding supports it for scripts

    def __exit__(self, *exc):
        if self.wm:
            self.wm.progress_end()


def generate(values, context):
    """A core.Heightfield for the settings (caller closes it)."""
    from .panels import preferences  # late import: panels imports the operators
    reference = reference_for(values)
    prefs = preferences(context)
    with WindowProgress(context) as progress:
        return core.generate_terrain(values, reference=reference, progress=progress,
                                     threads=prefs.threads if prefs else 0)


def new_terrain_mesh(values, context, name="Fractal Terrain"):
    """(mesh, summary): a new mesh datablock holding the terrain of `values`."""
    t0 = time.perf_counter()
    with generate(values, context) as hf:
        g = grid_arrays(hf, values["world_size"], z_floor(values), uvs=values["uvs"])
    mesh = bpy.data.meshes.new(name)
    try:
        mesh_build.fill_grid_mesh(mesh, g, smooth=values["smooth"])
    except BaseException:
        bpy.data.meshes.remove(mesh)
        raise
    return mesh, f"{g.nx} x {g.ny} vertices in {time.perf_counter() - t0:.2f} s"


def regenerate_object(obj, context):
    """Regenerates a terrain object from its stored settings.

    When the grid size is unchanged only the vertex positions are rewritten
    (one foreach_set); otherwise the mesh geometry is rebuilt. Returns a
    summary string.
    """
    settings = obj.fracterra_terrain
    values = params.values_of(settings)
    mesh = obj.data
    t0 = time.perf_counter()
    with generate(values, context) as hf:
        nx, ny = hf.width, hf.height
        same_grid = len(mesh.vertices) == nx * ny and len(mesh.polygons) == (nx - 1) * (ny - 1)
        if same_grid:
            size_x, size_y = grid_size(values["world_size"], nx, ny)
            co = vertices(hf, size_x, size_y, z_floor(values))
            mesh_build.rewrite_positions(mesh, co)
            if values["uvs"] != (mesh.uv_layers.get(mesh_build.UV_NAME) is not None):
                mesh_build.set_uvs(mesh, grid_arrays(hf, values["world_size"], uvs=True).uv
                                   if values["uvs"] else None)
            mesh_build.set_smooth(mesh, values["smooth"])
            how = "heights rewritten"
        else:
            g = grid_arrays(hf, values["world_size"], z_floor(values), uvs=values["uvs"])
            mesh_build.fill_grid_mesh(mesh, g, smooth=values["smooth"])
            how = "mesh rebuilt"
    return f"{nx} x {ny} terrain {how} in {time.perf_counter() - t0:.2f} s"
