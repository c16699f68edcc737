# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on's own settings, beside the library's (params.py): where a
terrain's reference points and falloff mask come from, its colours and mesh
options, the Erode step's preset and maps, Rivers and Lakes, a polyline's base,
Fractalize's and a planet's Blender-only settings; and the tables of every
operator and object (_tables: TERRAIN_PARAMS, ERODE_PARAMS, ...), which
params.py makes on first use."""

from dataclasses import replace

from .blender_overrides import _largest_levels
from .mesh_limits import cube_sphere_too_large
from .params import Param, _description, library_params


# Enum items: (identifier, label, tooltip, C value).
REFERENCE_SOURCES = (
    ("NONE", "None", "No reference points: a free fractal terrain", 0),
    ("OBJECT", "Grid Object", "Heights of a mesh whose vertices form a (2^m + 1)^2 grid", 1),
    ("IMAGE", "Image", "An image resampled to (2^m + 1)^2 reference points", 2),
    ("DEM", "DEM File", "A digital elevation model (GeoTIFF, .hgt, ASCII grid, ... read by GDAL) resampled "
     "to (2^m + 1)^2 reference points, in its true proportions", 3),
)

FALLOFF_MASK_SOURCES = (
    ("OBJECT", "Object", "The outline of a mesh or curve object seen from above", 0),
    ("IMAGE", "Image", "The brightness of an image (white keeps the height)", 1),
)


# Where the reference points come from (midpoint and additions): Blender's own terrain settings.
def _blender_terrain_params(dyadic):
    return (
        Param("reference_source", "enum", "NONE", "Reference", "Coarse heights the terrain must pass through",
              items=REFERENCE_SOURCES, methods=dyadic),
        Param("reference_object", "string", "", "Grid Object",
              "Mesh whose (2^m + 1)^2 vertices give the reference heights (local z, sorted by y then x)",
              methods=dyadic),
        Param("reference_image", "string", "", "Image", "Image whose brightness gives the reference heights",
              methods=dyadic),
        Param("reference_file", "string", "", "DEM File",
              "Elevation raster whose heights become the reference points (any format GDAL reads; holes are "
              "filled by GDAL's inverse-distance fill)", subtype="FILE_PATH", methods=dyadic),
        Param("reference_levels", "int", 4, "Reference Levels",
              "The image or DEM is resampled to 2^m + 1 points per side (at most Levels)", min=1, max=12,
              methods=dyadic),
        # Preview and Final: Auto Update edits at the Preview level, Regenerate builds Levels.
        Param("preview_levels", "int", 8, "Preview Levels",
              "Auto Update (and the redo panel, for a larger terrain) builds at this level, (2^n + 1)^2 "
              "vertices, so editing stays interactive; Regenerate builds the Final level (Levels). The two are "
              "the same terrain: more levels only add detail",
              min=1, max=_largest_levels(), methods=dyadic),
        Param("reference_height", "float", 5.0, "Image Height",
              "Height of white in the image; for a DEM without georeferencing, the height of its highest point "
              "above its lowest (scene units)",
              soft_min=-1000.0, soft_max=1000.0, subtype="DISTANCE", unit="LENGTH", methods=dyadic),
        # Where the custom falloff's mask comes from (Falloff 'Custom'; blender/build/falloff_mask.py).
        Param("falloff_mask_source", "enum", "OBJECT", "Mask From",
              "What gives the custom falloff's mask, spanning the terrain", items=FALLOFF_MASK_SOURCES),
        Param("falloff_mask_object", "string", "", "Mask Object",
              "Mesh or curve whose outline seen from above (its faces, or a closed curve's inside, projected on "
              "the terrain's footprint) keeps the heights; outside it they fall to the Edge Level"),
        Param("falloff_mask_image", "string", "", "Mask Image",
              "Image spanning the terrain: white keeps the height, black gives the Edge Level, grey between"),
        Param("falloff_mask_soft", "bool", True, "Soft Edge",
              "Fade the object's outline inward over the Falloff Width (a smoothstep); off: a step at the "
              "outline"),
        # The terrain's colours (the material's Base Color, the POV-Ray export's texture).
        Param("splat_rules", "string", "", "Material Rules",
              "Splat rules: a JSON file of layers ({\"layers\": [{\"name\": ..., \"slope_min\": ...}]}, as "
              "fracterra splat --rules reads it) that colour the terrain by height, slope and erosion; blank: the "
              "built-in grass, rock, sediment and snow",
              subtype="FILE_PATH"),
        # Mesh options.
        Param("uvs", "bool", True, "UVs", "Add a UV map spanning the grid 0..1", geometry=True),
        Param("smooth", "bool", True, "Smooth Shading", "Shade faces smooth", geometry=True),
    )


# The Erode step after generation (core/erosion.py runs it, blender/build/erosion.py
# draws it): its own table, ft_erosion_params as the library describes it, after
# the preset that fills it. A terrain object stores it beside the terrain's
# settings, so Regenerate reruns generation then erosion.
# The presets are the library's (ft_build_params.erosion_preset: ids, labels,
# tooltips); Custom is Blender's own. Blender stores an enum's number in the
# .blend: Custom keeps the 5 it had before Badlands came, Badlands takes 6.
_CUSTOM_PRESET = ("CUSTOM", "Custom", "Your own erosion: the settings below as set (a preset's, once you "
                  "change one)", 5)
_PRESET_NUMBER = {"BADLANDS": 6}


def _erode_preset(build_rows):
    """The erode_preset Param: the library's presets, then Custom."""
    row = next(r for r in build_rows if r["name"] == "erosion_preset")
    items = tuple((i["name"], i["label"], i["doc"], _PRESET_NUMBER.get(i["name"], i["value"])) for i in row["items"])
    return Param("erode_preset", "enum", "NONE", "Erosion",
                 "Erode after generating: a preset sets Duration and the Advanced settings; changing one of "
                 "them makes it Custom", items=items + (_CUSTOM_PRESET,))


# Where erosion acts and where rain falls (ft_erosion_params' erosion_mask and
# rain_map, sampled by blender/build/erosion_masks.py): Blender's own settings,
# kept on the terrain object with the rest, so Regenerate reruns them.
MAP_SOURCES = (
    ("NONE", "Everywhere", "No map: everywhere alike", 0),
    ("VERTEX_GROUP", "Vertex Group", "The weights of a vertex group painted on the terrain (Weight Paint)", 1),
    ("IMAGE", "Image", "The brightness of an image spanning the terrain", 2),
)
EROSION_MAP_PARAMS = (
    Param("erosion_mask_source", "enum", "NONE", "Mask",
          "Where erosion acts: weight or brightness 1 erodes fully, 0 leaves the ground untouched (material "
          "worn away inside may still settle outside)", items=MAP_SOURCES),
    Param("erosion_mask_group", "string", "", "Vertex Group", "The vertex group whose weights say where erosion acts"),
    Param("erosion_mask_image", "string", "", "Image", "The image whose brightness says where erosion acts"),
    Param("rain_map_source", "enum", "NONE", "Rain Map",
          "Where rain falls: weight or brightness 1 gets the full rainfall, 0 none", items=MAP_SOURCES),
    Param("rain_map_group", "string", "", "Vertex Group", "The vertex group whose weights say where rain falls"),
    Param("rain_map_image", "string", "", "Image", "The image whose brightness says where rain falls"),
)

# Rivers and Lakes (fracterra/hydrology.h), the pipeline's last stage: a
# terrain object stores them beside its settings (ft_hydrology_params' fields
# prefixed "rivers_": seed, tolerance and smoothing are names the terrain's
# settings have already), so Regenerate retraces them.
RIVERS = Param("rivers", "bool", False, "Rivers and Lakes",
               "Trace the terrain's rivers, lakes and sea after generating (and eroding) it: rivers as curves as "
               "wide as their discharge, lakes and the sea as flat water, parented to the terrain")
RIVERS_PREFIX = "rivers_"


def _rivers_params():
    return (RIVERS,) + tuple(replace(p, name=RIVERS_PREFIX + p.name) for p in library_params("hydrology"))


# Polylines (fracterra/polyline.h): Blender's own settings after the library's
# (where the base comes from, the curve's bevel).
BASE_SOURCES = (
    ("POINTS", "Two Points", "From Start to End", 0),
    ("ACTIVE", "Active Object", "Through the points of the active curve, or the edge chain of the active mesh", 1),
)
_BLENDER_POLYLINE_PARAMS = (
    Param("base_source", "enum", "POINTS", "Base", "The base polyline the fractal follows", items=BASE_SOURCES),
    # A vertical bolt striking the 3D cursor from 10 m above (in the object's frame).
    Param("start", "vector", (0.0, 0.0, 10.0), "Start", "First point of the base segment",
          subtype="TRANSLATION", unit="LENGTH"),
    Param("end", "vector", (0.0, 0.0, 0.0), "End", "Last point of the base segment",
          subtype="TRANSLATION", unit="LENGTH"),
    Param("bevel", "bool", True, "Bevel", "Give the curve thickness: bevel depth 1 times each point's radius"),
)
# Object > Fractalize (fracterra/subdiv.h): Blender's own settings after the library's.
_BLENDER_FRACTALIZE_PARAMS = (
    Param("use_creases", "bool", True, "Edge Creases", "Honour the mesh's edge creases (crease c becomes "
          "OpenSubdiv sharpness 10 c^2, as Blender's own subdivision)"),
    Param("smooth", "bool", True, "Smooth Shading", "Shade the fractal surface smooth (off: every facet flat)"),
)


# Add > Mesh > Fractal Planet (fracterra/planet.h): Blender's own settings after
# the library's: the mesh's levels (ft_planet_mesh's argument, not a field) and
# how the planet stands in the scene.
def _largest_planet_level():
    return max(n for n in range(0, 13) if cube_sphere_too_large(n) is None)


def _blender_planet_params():
    top = _largest_planet_level()
    return (
        Param("level", "int", 8, "Level",
              "Cube-face level n of the Final mesh: 6 x 4^n quads (8: 393 216, 10: 6.3 M; 11, 25 M, is the most a "
              "Blender mesh holds). Regenerate builds it",
              min=0, max=top, geometry=True),
        Param("preview_level", "int", 6, "Preview Level",
              "Auto Update (and the redo panel) builds at this level so editing stays interactive; the Preview "
              "is the Final's every 2^k-th sample, the same planet with less detail", min=0, max=top),
        # 60: the default planet's land rises 1.25 % of its radius above the sea, whose
        # shading the default view shows (at 20, 0.4 %: a flat disc of colour).
        Param("vertical_scale", "float", 60.0, "Exaggeration",
              "Heights times this: at 1 an Earth's 8 km mountains are 0.1 % of its radius, invisible from space",
              min=0.0, soft_max=200.0, precision=1),
        Param("scene_radius", "float", 1.0, "Scene Radius",
              "The planet's radius in the scene (the Radius setting is the planet's own, in metres, which the "
              "noise's scale and the heights are relative to); heights are scaled alike",
              min=1e-6, soft_max=100.0, subtype="DISTANCE", unit="LENGTH"),
        Param("sea_sphere", "bool", True, "Sea Sphere",
              "A water sphere at the sea's height, a child of the planet (with a Sea)"),
    )


def _tables():
    """The tables made from the library's description: built on first use, so
    importing this module loads no library (a script, a Dask worker, the
    add-on's registration order decide when)."""
    library_terrain = library_params("terrain")
    # The methods that make (2^levels + 1)^2 grids: those that use `levels`.
    dyadic = next(p for p in library_terrain if p.name == "levels").methods
    terrain = library_terrain + _blender_terrain_params(dyadic)
    erosion = library_params("erosion")
    erode = (_erode_preset(_description()["build"]),) + erosion + EROSION_MAP_PARAMS
    rivers = _rivers_params()
    return {
        "DYADIC_METHODS": dyadic,
        "TERRAIN_PARAMS": terrain,  # ft_terrain_params' settings and Blender's own for a terrain
        "EROSION_PARAMS": erosion,  # ft_erosion_params' settings
        "ERODE_PARAMS": erode,  # the Erode step: its preset, then ft_erosion_params' settings
        "RIVERS_PARAMS": rivers,  # Rivers and Lakes: the switch, then ft_hydrology_params' settings
        "TERRAIN_OBJECT_PARAMS": terrain + erode + rivers,  # what a terrain object stores
        "PARAMS_BY_NAME": {p.name: p for p in terrain + erode + rivers},
        "POLYLINE_PARAMS": library_params("polyline") + _BLENDER_POLYLINE_PARAMS,
        "FRACTALIZE_PARAMS": library_params("fractalize") + _BLENDER_FRACTALIZE_PARAMS,
        "PLANET_PARAMS": library_params("planet"),  # ft_planet_params' settings
        "PLANET_OBJECT_PARAMS": library_params("planet") + _blender_planet_params(),  # what a planet object stores
    }
