"""The one definition of every terrain setting.

Each Param names its property (shared with the library and the CLI where the
library has the field), its type, default, range, unit and tooltip. The
Blender side turns the list into operator properties and into the
PropertyGroup stored on terrain objects; `fill_struct` copies the values into
the C struct. Params without `field` are used by the add-on only (world size,
sea level, reference source, UVs...).
"""

import math
from dataclasses import dataclass, field as dc_field

# Where the add-on's default differs from the library's, and why: the only
# place such a difference may be stated (tests/python/test_params.py checks
# every other default against the library's table).
_INTERACTIVE = ("Blender regenerates the terrain while a slider is dragged: 257^2 vertices keep that "
                "interactive (0.1 s), the library's 513^2 is a CLI default for files")
BLENDER_OVERRIDES = {
    "terrain": {
        "levels": (8, _INTERACTIVE),
        "width": (257, _INTERACTIVE),
        "height": (257, _INTERACTIVE),
    },
    "polyline": {
        "method": ("FPL3D", "Add > Curve > Fractal Polyline starts as a lightning bolt, which must not be "
                            "flat: FPL 3D displaces it in all three axes"),
        "branch_prob": (0.3, "a lightning bolt forks; 0.3 gives a few side branches at depth 8"),
        "ifs_points": (20000, "every IFS point becomes a one-point spline of a curve object; 100 000 of "
                              "them take Blender seconds to build and draw"),
    },
}

# Enum items: (identifier, label, tooltip, C value).
METHODS = (
    ("MIDPOINT", "Midpoint", "Voss midpoint displacement (diamond-square), (2^levels + 1)^2 samples", 0),
    ("ADDITIONS", "Additions", "Voss/Feder successive random additions, (2^levels + 1)^2 samples", 1),
    ("FBM", "fBm Noise", "Sum of noise octaves with gain 2^-H (Quilez), any resolution", 2),
    ("SPECTRAL", "Spectral", "Inverse-FFT spectral synthesis, any resolution, tiles seamlessly", 3),
    ("INTERPOLATED", "Interpolated", "Saupe's InterpolatedFM: scale shrinks by 1/lacunarity per cycle", 4),
    ("MANDELBROT", "Mandelbrot", "The Mandelbrot set: smooth escape time of z <- z^2 + c, the set a plateau", 5),
)
DYADIC_METHODS = {"MIDPOINT", "ADDITIONS"}
BASES = (
    ("VALUE", "Value", "Value noise", 0),
    ("GRADIENT", "Gradient", "Perlin gradient noise", 1),
    ("SIMPLEX", "Simplex", "Simplex noise", 2),
    ("CELLULAR_F1", "Cellular F1", "Voronoi distance to the nearest feature point", 3),
    ("CELLULAR_F2F1", "Cellular F2-F1", "Voronoi F2 - F1: ridges between cells", 4),
)
VARIANTS = (
    ("STANDARD", "Standard", "Plain fBm sum of octaves", 0),
    ("RIDGED", "Ridged", "Ridged multifractal: sharp crests", 1),
    ("HYBRID", "Hybrid", "Musgrave's hybrid multifractal: smooth valleys, rough peaks", 2),
    ("HETERO", "Hetero", "Musgrave's heterogeneous terrain", 3),
)
REFERENCE_SCALES = (
    ("SIGMA", "Sigma", "Displace the refinement by sigma as given", 0),
    ("MEAN", "Mean", "Scale the refinement by the mean of |reference values|", 1),
    ("STD", "Std Dev", "Scale the refinement by the standard deviation of the reference values", 2),
)
REFERENCE_SOURCES = (
    ("NONE", "None", "No reference points: a free fractal terrain", 0),
    ("OBJECT", "Grid Object", "Heights of a mesh whose vertices form a (2^m + 1)^2 grid", 1),
    ("IMAGE", "Image", "An image resampled to (2^m + 1)^2 reference points", 2),
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
    methods: frozenset = dc_field(default=None)  # methods that use it; None: all
    geometry: bool = False  # changing it changes the vertex count (rebuild, not rewrite)

    def c_value(self, value):
        """The value as the C struct stores it."""
        if self.kind == "enum":
            return next(item[3] for item in self.items if item[0] == value)
        if self.kind == "bool":
            return 1 if value else 0
        return value


_NOISE = frozenset({"FBM"})
_FREE = frozenset({"FBM", "SPECTRAL", "INTERPOLATED", "MANDELBROT"})
_MANDELBROT = frozenset({"MANDELBROT"})
_RANDOM_TERRAIN = frozenset({"MIDPOINT", "ADDITIONS", "FBM", "SPECTRAL", "INTERPOLATED"})
_DYADIC = frozenset(DYADIC_METHODS)

TERRAIN_PARAMS = (
    Param("method", "enum", "MIDPOINT", "Method", "How the terrain is synthesised", items=METHODS,
          field="method", geometry=True),
    Param("levels", "int", 8, "Levels",
          "Refinement steps: the grid has 2^levels + 1 vertices per side (8: 257, 10: 1025)",
          min=1, max=13, soft_max=12, field="levels", methods=_DYADIC, geometry=True),
    Param("width", "int", 257, "Samples X", "Vertices along X (methods other than midpoint/additions)",
          min=2, max=8193, field="width", methods=_FREE, geometry=True),
    Param("height", "int", 257, "Samples Y", "Vertices along Y (methods other than midpoint/additions)",
          min=2, max=8193, field="height", methods=_FREE, geometry=True),
    Param("hurst", "float", 0.8, "Hurst H",
          "Hurst exponent: 0 is rough (fractal dimension 3), 1 is smooth (dimension 2)",
          min=0.0, max=1.0, subtype="FACTOR", field="hurst", precision=3, methods=_RANDOM_TERRAIN),
    Param("sigma", "float", 1.0, "Sigma",
          "Vertical scale: standard deviation of the first displacement, in scene units",
          min=1e-6, max=1e6, soft_max=100.0, subtype="DISTANCE", unit="LENGTH", field="sigma"),
    Param("seed", "int", 1, "Seed", "Random seed: the same seed gives the same terrain on every machine",
          min=0, max=2**31 - 1, field="seed", methods=_RANDOM_TERRAIN),
    Param("periodic", "bool", False, "Periodic", "Wrap-around neighbours: the terrain tiles seamlessly",
          field="periodic", methods=_RANDOM_TERRAIN),
    Param("world_size", "float", 10.0, "World Size", "Extent of the terrain along X in scene units "
          "(Y follows from the sample spacing)", min=1e-4, max=1e7, soft_max=10000.0,
          subtype="DISTANCE", unit="LENGTH", field="world_size"),
    Param("use_sea_level", "bool", False, "Sea Level", "Flatten everything below the sea level"),
    Param("sea_level", "float", 0.0, "Sea Level Height", "Heights below this become flat sea",
          soft_min=-100.0, soft_max=100.0, subtype="DISTANCE", unit="LENGTH"),
    # fBm and the interpolated variant.
    Param("octaves", "int", 8, "Octaves", "Noise octaves summed", min=1, max=30, field="octaves",
          methods=_NOISE),
    Param("lacunarity", "float", 2.0, "Lacunarity",
          "Frequency ratio between octaves (fBm) or scale factor per cycle (interpolated)",
          min=1.01, max=16.0, soft_max=4.0, field="lacunarity", methods=frozenset({"FBM", "INTERPOLATED"})),
    Param("gain", "float", 0.0, "Gain", "Amplitude ratio between octaves; 0 uses 2^-H",
          min=0.0, max=1.0, subtype="FACTOR", field="gain", methods=_NOISE),
    Param("basis", "enum", "GRADIENT", "Basis", "Noise function of each octave", items=BASES,
          field="basis", methods=_NOISE),
    Param("variant", "enum", "STANDARD", "Variant", "How octaves combine", items=VARIANTS,
          field="variant", methods=_NOISE),
    Param("frequency", "float", 4.0, "Frequency", "Base frequency in cycles across the width",
          min=1e-3, max=1e4, soft_max=64.0, field="frequency", methods=_NOISE),
    Param("offset", "float", 1.0, "Offset", "Offset of the ridged, hybrid and hetero variants",
          min=-10.0, max=10.0, field="offset", methods=_NOISE),
    Param("octave_rotation", "float", 0.5, "Octave Rotation", "Domain rotation per octave (hides octave alignment)",
          min=-math.pi, max=math.pi, subtype="ANGLE", unit="ROTATION", field="octave_rotation", methods=_NOISE),
    Param("warp", "float", 0.0, "Warp", "Domain-warp strength (0 = off)", min=0.0, max=10.0,
          field="warp", methods=_NOISE),
    # The Mandelbrot set (seed 002).
    Param("center_x", "float", -0.5, "Center X", "Real part of the view's centre in the complex plane",
          min=-4.0, max=4.0, soft_min=-2.0, soft_max=1.0, field="center_x", precision=6, methods=_MANDELBROT),
    Param("center_y", "float", 0.0, "Center Y", "Imaginary part of the view's centre", min=-4.0, max=4.0,
          soft_min=-1.5, soft_max=1.5, field="center_y", precision=6, methods=_MANDELBROT),
    Param("zoom", "float", 1.0, "Zoom", "The width spans 4 / zoom of the plane; refused beyond double "
          "precision (about 1e11 at 1025 samples across)", min=1e-3, max=1e15, soft_min=0.5, soft_max=1e6,
          field="zoom", methods=_MANDELBROT),
    Param("iterations", "int", 64, "Iterations", "Maximum iterations: points that have not escaped are the "
          "set, a plateau; fewer make a lower wall where the slopes meet it", min=1, max=2**24,
          soft_max=4096, field="iterations", methods=_MANDELBROT),
    Param("supersample", "int", 2, "Supersample", "k x k points averaged per vertex (smooths the boundary; "
          "k^2 times the work)", min=1, max=8, field="supersample", methods=_MANDELBROT),
    # Reference points (midpoint and additions).
    Param("reference_source", "enum", "NONE", "Reference", "Coarse heights the terrain must pass through",
          items=REFERENCE_SOURCES, methods=_DYADIC),
    Param("reference_object", "string", "", "Grid Object",
          "Mesh whose (2^m + 1)^2 vertices give the reference heights (local z, sorted by y then x)",
          methods=_DYADIC),
    Param("reference_image", "string", "", "Image", "Image whose brightness gives the reference heights",
          methods=_DYADIC),
    Param("reference_levels", "int", 4, "Reference Levels",
          "The image is resampled to 2^m + 1 points per side (at most Levels)", min=1, max=13,
          methods=_DYADIC),
    Param("reference_height", "float", 5.0, "Image Height", "Height of white in the image, in scene units",
          soft_min=-1000.0, soft_max=1000.0, subtype="DISTANCE", unit="LENGTH", methods=_DYADIC),
    Param("reference_scale", "enum", "SIGMA", "Refinement Scale",
          "Displacement scale of the steps after the reference grid", items=REFERENCE_SCALES,
          field="reference_scale", methods=_DYADIC),
    # Mesh options.
    Param("uvs", "bool", True, "UVs", "Add a UV map spanning the grid 0..1", geometry=True),
    Param("smooth", "bool", True, "Smooth Shading", "Shade faces smooth", geometry=True),
)

PARAMS_BY_NAME = {p.name: p for p in TERRAIN_PARAMS}


def defaults():
    """{name: default} for every terrain setting."""
    return {p.name: p.default for p in TERRAIN_PARAMS}


def is_used(param, method):
    """True when `param` matters for `method` (used to lay out panels)."""
    return param.methods is None or method in param.methods


def fill_struct(struct, values, param_list=None):
    """Copies the values that have a C field into a ctypes params struct
    (ft_terrain_params unless another list is given).

    `values` maps names to values; names it lacks keep the struct's value.
    """
    for p in param_list or TERRAIN_PARAMS:
        if p.field and p.name in values:
            setattr(struct, p.field, p.c_value(values[p.name]))
    return struct


def values_of(obj, param_list=None):
    """{name: value} read from an object whose attributes are the settings."""
    return {p.name: (tuple(v) if p.kind == "vector" else v)
            for p in param_list or TERRAIN_PARAMS for v in [getattr(obj, p.name)]}


# Polylines (fracterra/polyline.h). Names shared with the library and the CLI:
# method, rng, spread, depth, min_length, seed.
POLYLINE_METHODS = (
    ("FPL", "FPL 2D", "Nikulin's fractal polyline: random orthogonal midpoint displacement in the XY plane", 0),
    ("FPL3D", "FPL 3D", "Fractal polyline with 3D displacements (lightning)", 1),
    ("KOCH", "Koch", "Koch curve on every base segment", 2),
    ("DRAGON", "Dragon", "Harter-Heighway dragon", 3),
    ("SIERPINSKI", "Sierpinski", "Sierpinski arrowhead curve", 4),
    ("IFS", "IFS Points", "Attractor of an iterated function system, as a point cloud", 5),
    ("PROFILE", "Profile", "Voss 1D midpoint profile laid across every base segment (a horizon)", 6),
)
POLYLINE_RNGS = (
    ("UNIFORM", "Uniform", "Displacements uniform on [-s, s]", 0),
    ("NORMAL", "Normal", "Displacements normal with standard deviation s", 1),
)
IFS_PRESETS = (
    ("FERN", "Fern", "Barnsley's fern", 0),
    ("DRAGON", "Dragon", "Harter-Heighway dragon", 1),
    ("KOCH", "Koch", "Koch curve", 2),
    ("SIERPINSKI_GASKET", "Sierpinski Gasket", "Three maps of ratio 1/2 (dimension log 3 / log 2)", 3),
)
BASE_SOURCES = (
    ("POINTS", "Two Points", "From Start to End", 0),
    ("ACTIVE", "Active Object", "Through the points of the active curve, or the edge chain of the active mesh", 1),
)
_FPL = frozenset({"FPL", "FPL3D"})
_RANDOM = frozenset({"FPL", "FPL3D", "PROFILE", "IFS"})

POLYLINE_PARAMS = (
    Param("method", "enum", "FPL3D", "Method", "Which fractal curve", items=POLYLINE_METHODS, field="method"),
    Param("rng", "enum", "UNIFORM", "Generator", "Random generator of the displacements", items=POLYLINE_RNGS,
          field="rng", methods=_FPL),
    Param("spread", "float", 0.1, "Spread", "Displacement per unit segment length: s (uniform) or sigma "
          "(normal). Below 0.1 lightning-like, 0.2-0.3 horizon-like, 0.3+ Brownian loops; profile: sigma",
          min=0.0, max=10.0, soft_max=1.0, field="spread", methods=frozenset({"FPL", "FPL3D", "PROFILE"})),
    Param("depth", "int", 8, "Depth", "Recursion depth r: each base segment gets up to 2^r segments "
          "(Koch 4^r, Sierpinski 3^r)", min=0, max=20, soft_max=14, field="depth"),
    Param("min_length", "float", 0.0, "Min Length", "Segments shorter than this are not split (delta)",
          min=0.0, max=1e6, subtype="DISTANCE", unit="LENGTH", field="min_length", methods=_FPL),
    Param("seed", "int", 1, "Seed", "Random seed", min=0, max=2**31 - 1, field="seed", methods=_RANDOM),
    Param("branch_prob", "float", 0.3, "Branching", "Probability that a midpoint forks a side branch "
          "(scaled by 2^(-level/2)); 0 = a single line", min=0.0, max=1.0, subtype="FACTOR",
          field="branch_prob", methods=_FPL),
    Param("branch_decay", "float", 0.5, "Branch Decay", "Length and radius factor per branch generation",
          min=0.01, max=0.99, subtype="FACTOR", field="branch_decay", methods=_FPL),
    Param("branch_generations", "int", 3, "Branch Generations", "Deepest branch generation", min=1, max=8,
          field="branch_generations", methods=_FPL),
    Param("hurst", "float", 0.8, "Hurst H", "Hurst exponent of the profile", min=0.0, max=1.0,
          subtype="FACTOR", field="hurst", methods=frozenset({"PROFILE"})),
    Param("ifs_preset", "enum", "FERN", "IFS", "Built-in iterated function system", items=IFS_PRESETS,
          field="ifs_preset", methods=frozenset({"IFS"})),
    Param("ifs_points", "int", 20000, "Points", "Attractor points", min=1, max=10_000_000,
          field="ifs_points", methods=frozenset({"IFS"})),
    Param("radius", "float", 0.01, "Radius", "Radius at the start of the main line (branches taper)",
          min=0.0, max=1e4, soft_max=1.0, subtype="DISTANCE", unit="LENGTH", field="radius"),
    Param("base_source", "enum", "POINTS", "Base", "The base polyline the fractal follows", items=BASE_SOURCES),
    # A vertical bolt striking the 3D cursor from 10 m above (in the object's frame).
    Param("start", "vector", (0.0, 0.0, 10.0), "Start", "First point of the base segment",
          subtype="TRANSLATION", unit="LENGTH"),
    Param("end", "vector", (0.0, 0.0, 0.0), "End", "Last point of the base segment",
          subtype="TRANSLATION", unit="LENGTH"),
    Param("bevel", "bool", True, "Bevel", "Give the curve thickness: bevel depth 1 times each point's radius"),
)

