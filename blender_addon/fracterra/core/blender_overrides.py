# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the add-on differs from the library's parameter tables, each with its
reason, stated once: the defaults Blender starts from, the limits narrower than
the library's (Blender's own: a mesh's size, a 32-bit IntProperty), the fields
that are not Blender properties, and how Blender shows a field (subtype, unit,
precision, a display scale). params.py applies them to the library's rows."""

import math

from .mesh_limits import too_large

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
