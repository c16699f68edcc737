"""The settings of the add-on, made from the library's own description of its
parameter structs (fracterra/params.h): names, defaults, ranges, enum items,
labels, tooltips and which methods use each field come from the library's
tables. What is the add-on's own is stated here, once: the defaults and
limits where Blender differs from the library (each with its reason) and the
settings that exist only in Blender (sea level, reference source, UVs...).

Each Param names its property (the C field's name, shared with the CLI), its
type, default, range and tooltip. The Blender side turns the list into
operator properties and into the PropertyGroup stored on terrain objects;
`fill_struct` copies the values into the C struct.

The description comes from the loaded library, or, when it cannot be loaded
(the add-on still registers and says what to do), from `params.json`, the
same tables written by `fracterra params --json` when the add-on zip was
built beside its library.
"""

import json
import math
from dataclasses import dataclass, field as dc_field, replace
from pathlib import Path

from .binding import PARAMS_KINDS, library
from .rows import row_from_json
from .errors import LibraryNotFoundError
from .mesh_limits import cube_sphere_too_large, too_large

# Where the add-on's default differs from the library's, and why: the only
# place such a difference may be stated (tests/python/test_params.py checks
# every other default against the library's table).
_INTERACTIVE = ("Blender regenerates the terrain while a slider is dragged: 257^2 vertices keep that "
                "interactive (0.1 s), the library's 513^2 is a CLI default for files")
# Add > Mesh > Fractal Terrain starts as a landform an artist recognises (a
# mountain falling off to a flat edge, as A.N.T. Landscape's default does)
# rather than the raw method, a tilted slab (issue 17). The library keeps
# neutral landform defaults: files and goldens made before them are unchanged.
_LANDFORM = "the default is a mountain on a flat edge: levelled, raised and faded out radially"
BLENDER_OVERRIDES = {
    "terrain": {
        "levels": (8, _INTERACTIVE),
        "width": (257, _INTERACTIVE),
        "height": (257, _INTERACTIVE),
        "sigma": (2.0, "with the raise and falloff below a relief of about a quarter of the width (2-3 m on "
                       "10 m; A.N.T.: 0.5 on 2)"),
        "levelling": (1.0, _LANDFORM + ": without levelling the first corners tilt the whole terrain"),
        "height_offset": (1.5, _LANDFORM + ": raised so that the falloff shapes a mountain, not a crater"),
        "falloff": ("RADIAL", _LANDFORM + ": no walls at the edges"),
        "falloff_width": (0.9, _LANDFORM + ": from the centre, so the outline is a round mountain"),
    },
    "polyline": {
        "method": ("FPL3D", "Add > Curve > Fractal Polyline starts as a lightning bolt, which must not be "
                            "flat: FPL 3D displaces it in all three axes"),
        "branch_prob": (0.3, "a lightning bolt forks; 0.3 gives a few side branches at depth 8"),
        "ifs_points": (20000, "every IFS point becomes a one-point spline of a curve object; 100 000 of "
                              "them take Blender seconds to build and draw"),
    },
    "planet": {
        "sea": ("FRACTION", "Add > Mesh > Fractal Planet starts as a globe with oceans (70 %, the Earth's 71 %), "
                            "the picture a new user expects; the library's planet has no sea unless asked"),
    },
    "fractalize": {
        "levels": (3, "the redo panel runs Fractalize again on every change: 3 levels (64 faces per base "
                      "face) answer at once, the library's 4 takes four times as long for each tweak"),
    },
}

# Limits of Blender that are narrower than the library's hard range: (min, max, reason).
def _largest_levels():
    return max(n for n in range(1, 16) if too_large(2 ** n + 1, 2 ** n + 1) is None)


_MESH = ("a Blender mesh array holds at most 2 GiB (core/mesh_limits.py): levels 13 (8193^2 vertices, "
         "2^28 face corners) overflows it, so Blender does not offer it; the CLI makes such terrains as files. "
         "Width x height is checked the same way before any work")
_INT32 = "Blender's IntProperty is a signed 32-bit integer"
_CURVE_POINTS = ("every point becomes a spline point of a Blender curve: 2^20 per base segment (depth 20) "
                 "already takes seconds to build and draw; the CLI writes deeper ones to files")
BLENDER_LIMITS = {
    "terrain": {
        "levels": (1, _largest_levels(), _MESH),
        "seed": (0, 2**31 - 1, _INT32),
    },
    "polyline": {
        "depth": (0, 20, _CURVE_POINTS),
        "seed": (0, 2**31 - 1, _INT32),
        "ifs_points": (1, 10_000_000, _CURVE_POINTS),
    },
    "fractalize": {
        "seed": (0, 2**31 - 1, _INT32),
    },
    "planet": {
        "seed": (0, 2**31 - 1, _INT32),
    },
}
# Library fields that are not Blender properties, and why.
_SEA = "the terrain's own sea (its Sea setting) is the rivers' and the erosion's sea, in the library's pipeline"
_THREADS = "set from the add-on preferences (Threads) for every operator"
NOT_PROPERTIES = {
    "terrain": {"threads": _THREADS},
    "polyline": {"threads": _THREADS},
    "fractalize": {"threads": _THREADS},
    "planet": {"threads": _THREADS},
    "erosion": {"threads": _THREADS,
                "periodic": "the terrain's own Periodic setting: a tiling terrain is eroded as a torus",
                "sea": _SEA, "sea_level": _SEA, "sea_fraction": _SEA},
    "hydrology": {"threads": _THREADS,
                  "periodic": "the library's pipeline: a terrain that tiles gives rivers that wrap",
                  "sea": _SEA, "sea_level": _SEA, "sea_fraction": _SEA,
                  "sink_count": "declared sinks are for the CLI and the library (sinks is a pointer)"},
}
# How Blender shows a field (subtype, unit, precision): presentation only.
_BY_UNIT = {"scene units": {"subtype": "DISTANCE", "unit": "LENGTH"},
            "world units": {"subtype": "DISTANCE", "unit": "LENGTH"},
            "radians": {"subtype": "ANGLE", "unit": "ROTATION"}}
_PRECISION = {"hurst": 3, "center_x": 6, "center_y": 6,
              "erodibility": 6, "uplift": 6,  # their defaults (2e-4, ~1e-5) are 0.000 at 3 digits
              "duration": 0}  # whole years: "100000.00" cut the label to "Dur" in the sidebar
# Blender shows at most 6 decimals: a float whose default is under 1e-4 (the
# diffusion's 1e-7 read 0.000000) is shown times the power of ten that brings
# its default to 1..10, the power in its label (props.display_property). The
# value stored and passed to the library stays the table's.
_SCALE_BELOW = 1e-4


def shown_name(name):
    """The Blender property that draws setting `name` scaled (blender/props.py display_property)."""
    return f"{name}_shown"


def display_scale_of(row):
    """The power of ten Blender shows the field of `row` times, or None."""
    default = row["default"]
    if row["type"] not in ("double", "float") or not 0 < default < _SCALE_BELOW:
        return None
    return 10.0 ** -math.floor(math.log10(default))
# Settings whose change changes the vertex count (rebuild, not rewrite).
_GEOMETRY = {"method", "levels", "width", "height"}
SNAPSHOT = Path(__file__).resolve().parent / "params.json"

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


@dataclass(frozen=True)
class Param:
    name: str
    kind: str  # 'int', 'float', 'bool', 'enum', 'string'
    default: object
    label: str
    description: str
    min: float = None
    max: float = None
    soft_min: float = None
    soft_max: float = None
    items: tuple = ()
    field: str = None  # the ft_terrain_params field, None for add-on-only settings
    subtype: str = "NONE"  # Blender subtype: 'DISTANCE', 'ANGLE', 'FACTOR', ...
    unit: str = "NONE"  # Blender unit: 'LENGTH', 'ROTATION'
    step: int = None
    precision: int = None
    display_scale: float = None  # Blender shows value x this (a power of ten); None: as is
    unit_text: str = ""  # a unit Blender cannot show itself ("years", "1/yr"): drawn beside the label
    methods: frozenset = dc_field(default=None)  # methods that use it; None: all
    geometry: bool = False  # changing it changes the vertex count (rebuild, not rewrite)

    def c_value(self, value):
        """The value as the C struct stores it."""
        if self.kind == "enum":
            return next(item[3] for item in self.items if item[0] == value)
        if self.kind == "bool":
            return 1 if value else 0
        return value


def _description():
    """{kind name: [rows]} from the loaded library, else from the snapshot beside this file (rows.py reads both)."""
    try:
        lib = library()
    except LibraryNotFoundError:
        if not SNAPSHOT.is_file():
            raise
        tables = json.loads(SNAPSHOT.read_text())
        # "ft_terrain_params" -> "terrain"
        return {name[3:-7]: [row_from_json(f) for f in table["fields"]] for name, table in tables.items()}
    return lib.param_rows


_KIND_OF_TYPE = {"int32": "int", "int64": "int", "uint64": "int", "double": "float", "float": "float",
                 "bool": "bool", "enum": "enum"}


def _param_from_row(row, kind_name, method_items):
    """The add-on's Param for one library field, with Blender's limits and overrides applied."""
    name = row["name"]
    kind = _KIND_OF_TYPE[row["type"]]
    items = tuple((i["name"], i["label"], i["doc"], i["value"]) for i in row.get("items") or ())
    default = row["default"]
    if kind == "enum":
        default = next(ident for ident, _l, _d, value in items if value == int(default))
    elif kind == "bool":
        default = bool(default)
    elif kind == "int":
        default = int(default)
    default = BLENDER_OVERRIDES.get(kind_name, {}).get(name, (default,))[0]
    lo, hi = row["hard_min"], row["hard_max"]
    if lo is not None and row["min_exclusive"]:
        lo += 1e-6 if lo == 0 else abs(lo) * 1e-6  # Blender has no open bound; the library refuses lo itself
    if hi is not None and row.get("max_exclusive"):
        hi -= 1e-6 if hi == 0 else abs(hi) * 1e-6
    if name in BLENDER_LIMITS.get(kind_name, {}):
        lo, hi, _reason = BLENDER_LIMITS[kind_name][name]
    soft_lo, soft_hi = row["soft_min"], row["soft_max"]
    if kind == "int":  # IntProperty bounds are 32-bit integers
        def fit(v):
            return None if v is None else int(min(max(v, -2**31), 2**31 - 1))
        lo, hi, soft_lo, soft_hi = fit(lo), fit(hi), fit(soft_lo), fit(soft_hi)
    methods = None
    if row["methods"] != 2**64 - 1 and method_items:
        methods = frozenset(ident for ident, _l, _d, value in method_items if row["methods"] >> value & 1)
    look = _BY_UNIT.get(row["unit"], {})
    if kind == "float" and not look and lo == 0 and hi == 1:
        look = {"subtype": "FACTOR"}
    description = row["doc"] + (f" ({row['unit']})" if row["unit"] and not look else "")
    # Units Blender has no unit for are drawn with the label ("Step Length (years)");
    # a count's unit is its label already ("River Steps" in steps).
    unit_text = row["unit"] if row["unit"] and not look and row["unit"] not in row["label"].lower() else ""
    numeric = kind in ("int", "float")
    return Param(name, kind, default, row["label"], description,
                 min=lo if numeric else None, max=hi if numeric else None,
                 soft_min=soft_lo if numeric else None, soft_max=soft_hi if numeric else None,
                 items=items, field=name, subtype=look.get("subtype", "NONE"), unit=look.get("unit", "NONE"),
                 precision=_PRECISION.get(name), display_scale=display_scale_of(row), unit_text=unit_text,
                 methods=methods,
                 geometry=name in _GEOMETRY)


def _check_names(kind_name, rows):
    """Every field an override table names is a field of the library's struct: a
    misspelt or removed name would otherwise change nothing, silently."""
    fields = {r["name"] for r in rows}
    for table_name, table in (("BLENDER_OVERRIDES", BLENDER_OVERRIDES), ("BLENDER_LIMITS", BLENDER_LIMITS),
                              ("NOT_PROPERTIES", NOT_PROPERTIES)):
        unknown = set(table.get(kind_name, {})) - fields
        if unknown:
            raise KeyError(f"{table_name}[{kind_name!r}] names {sorted(unknown)}, not fields of "
                           f"ft_{kind_name}_params")


def library_params(kind_name):
    """The add-on's Params for every setting of the library's struct `kind_name` ("terrain")."""
    if kind_name not in PARAMS_KINDS:
        raise KeyError(f"{kind_name!r} is not a params struct of the library ({', '.join(PARAMS_KINDS)})")
    rows = _description()[kind_name]
    _check_names(kind_name, rows)
    method = next((r for r in rows if r["name"] == "method"), None)
    method_items = tuple((i["name"], i["label"], i["doc"], i["value"]) for i in method["items"]) if method else ()
    skip = NOT_PROPERTIES.get(kind_name, {})
    return tuple(_param_from_row(r, kind_name, method_items) for r in rows
                 if r["type"] in _KIND_OF_TYPE and r["settable"] and r["count"] == 1 and r["name"] not in skip)


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


_LAZY = ("DYADIC_METHODS", "TERRAIN_PARAMS", "EROSION_PARAMS", "ERODE_PARAMS", "RIVERS_PARAMS", "TERRAIN_OBJECT_PARAMS",
         "PARAMS_BY_NAME", "POLYLINE_PARAMS", "FRACTALIZE_PARAMS", "PLANET_PARAMS", "PLANET_OBJECT_PARAMS")


def __getattr__(name):
    """params.TERRAIN_PARAMS and the other tables, made on first use (PEP 562)."""
    if name in _LAZY:
        globals().update(_tables())
        return globals()[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _table(name):
    return globals()[name] if name in globals() else __getattr__(name)


def defaults(param_list=None):
    """{name: default} for every setting a terrain object stores (unless another list is given)."""
    return {p.name: p.default for p in param_list or _table("TERRAIN_OBJECT_PARAMS")}


def is_used(param, method):
    """True when `param` matters for `method` (used to lay out panels)."""
    return param.methods is None or method in param.methods


def grid_shape(values):
    """(nx, ny) of the terrain that settings `values` (a dict) describe."""
    if values["method"] in _table("DYADIC_METHODS"):
        side = 2 ** values["levels"] + 1
        return side, side
    return values["width"], values["height"]


def preview_values(values):
    """The settings of the Preview of terrain `values`: Levels lowered to Preview
    Levels (never below a reference's own levels, which the preview must pass
    through too). The same settings when the method has no levels or the Final
    is no larger."""
    if values["method"] not in _table("DYADIC_METHODS"):
        return values
    floor = values["reference_levels"] if values.get("reference_source") in ("IMAGE", "DEM") else 1
    levels = min(values["levels"], max(values.get("preview_levels", values["levels"]), floor))
    return {**values, "levels": levels} if levels != values["levels"] else values


def planet_preview_values(values):
    """The settings of a planet's Preview: its Level lowered to Preview Level
    (the same settings when the Final is no larger)."""
    level = min(values["level"], values["preview_level"])
    return {**values, "level": level} if level != values["level"] else values


def fill_struct(struct, values, param_list=None):
    """Copies the values that have a C field into a ctypes params struct
    (ft_terrain_params unless another list is given).

    `values` maps names to values; names it lacks keep the struct's value.
    """
    for p in param_list or _table("TERRAIN_PARAMS"):
        if p.field and p.name in values:
            setattr(struct, p.field, p.c_value(values[p.name]))
    return struct


def values_of(obj, param_list=None):
    """{name: value} read from an object whose attributes are the settings
    (those a terrain object stores unless another list is given)."""
    return {p.name: (tuple(v) if p.kind == "vector" else v)
            for p in param_list or _table("TERRAIN_OBJECT_PARAMS") for v in [getattr(obj, p.name)]}
