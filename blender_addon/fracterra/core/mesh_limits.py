# SPDX-License-Identifier: GPL-3.0-or-later
"""How large a grid mesh Blender can hold and what it costs, decided from the
grid size alone, before any work (no bpy here).

Blender 3.x keeps each mesh element array (vertices, edges, face corners,
faces) in one allocation whose size in bytes is a C int. The widest records
are 16 bytes per vertex (MVert), 12 per edge (MEdge), 12 per face corner with
a UV map (MLoopUV; MLoop is 8) and 12 per face (MPoly), so an array beyond
2^31 - 1 bytes overflows. Levels 13 (8193^2 vertices, 2^28 face corners of
8 bytes = 2^31) is where it did: "Array length mismatch (expected -268435456,
got 268435456)" from loops.foreach_set after ~35 s and 11 GB. Blender 4
stores narrower per-attribute arrays; one limit serves both.
"""

from .errors import TooLargeError

INT_MAX = 2 ** 31 - 1
RECORD_BYTES = {"vertices": 16, "edges": 12, "face corners": 12, "faces": 12}

# Peak memory while adding a terrain, per vertex: measured in Blender 3.4
# (background, maxrss before/after Add Terrain) as 306 / 293 / 292 / 296
# bytes at levels 9 / 10 / 11 / 12 (levels 12: 16.8 M vertices, 4.7 GiB, built
# fine); the GUI's undo step keeps a copy of the mesh on top.
PEAK_BYTES_PER_VERTEX = 300
# From here on the operator shows the estimate (levels 10 and more).
SHOW_ESTIMATE_FROM = 1_000_000


def quad_grid_counts(nx, ny):
    """{element: count} of an nx x ny vertex quad grid, as fracterra/mesh.h builds it."""
    faces = (nx - 1) * (ny - 1)
    return {"vertices": nx * ny, "edges": nx * (ny - 1) + ny * (nx - 1), "face corners": 4 * faces,
            "faces": faces}


def too_large(nx, ny):
    """None when Blender can hold the grid, else why not (one sentence)."""
    for element, count in quad_grid_counts(nx, ny).items():
        if count * RECORD_BYTES[element] > INT_MAX:
            limit = INT_MAX // RECORD_BYTES[element]
            return (f"a {nx} x {ny} grid has {count:,} {element}, more than the {limit:,} a Blender mesh "
                    f"can hold ({RECORD_BYTES[element]} bytes each in one array of at most 2 GiB); "
                    "use levels 12 (4097 x 4097) or fewer, or tiles")
    return None


def cube_sphere_too_large(level):
    """None when a Blender mesh can hold the planet's cube-sphere of `level`
    (6 4^level quads, 6 4^level + 2 vertices), else why not, as too_large."""
    quads = 6 * 4 ** level
    counts = {"vertices": quads + 2, "edges": 2 * quads, "face corners": 4 * quads, "faces": quads}
    for element, count in counts.items():
        if count * RECORD_BYTES[element] > INT_MAX:
            return (f"level {level} has {count:,} {element}, more than the {INT_MAX // RECORD_BYTES[element]:,} "
                    f"a Blender mesh can hold; use level {level - 1} or less")
    return None


def check_grid(nx, ny):
    """Raises TooLargeError (reported by the operators) when Blender cannot hold the grid."""
    reason = too_large(nx, ny)
    if reason:
        raise TooLargeError(f"Refused before generating: {reason}")


def estimate(nx, ny):
    """'16.8 M vertices, about 5.0 GB of memory' for the status line and the redo panel."""
    n = nx * ny
    return f"{n / 1e6:.1f} M vertices, about {n * PEAK_BYTES_PER_VERTEX / 1e9:.1f} GB of memory"
