#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the seed corpora in tests/fuzz/corpus/<harness>/: one small valid
file per format and variant the readers accept, plus edge cases they must
refuse cleanly. Deterministic; rerun after changing it and commit the files.
Usage: /usr/bin/python3 tests/fuzz/make_corpus.py"""
import ctypes
import io
import json
import os
import struct
import sys
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")


def put(harness, name, data):
    d = os.path.join(CORPUS, harness)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# ---------------------------------------------------------------- PNG
def png(width, height, color_type, depth, rows, text=None, interlace=0, palette=None, trns=None):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, color_type, 0, 0, interlace))
    if palette:
        out += chunk(b"PLTE", palette)
    if trns:
        out += chunk(b"tRNS", trns)
    for k, v in (text or {}).items():
        out += chunk(b"tEXt", k.encode() + b"\0" + v.encode())
    raw = b"".join(b"\0" + r for r in rows)  # filter type 0 on every row
    return out + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def gray16(w, h):
    return [b"".join(struct.pack(">H", (x * 4099 + y * 977) & 0xFFFF) for x in range(w)) for y in range(h)]


def gray8(w, h):
    return [bytes(((x * 37 + y * 11) & 0xFF) for x in range(w)) for y in range(h)]


pngs = {
    "gray16_5x5_range.png": png(5, 5, 0, 16, gray16(5, 5), {"fracterra:min": "-1.5", "fracterra:max": "2.25"}),
    "gray8_3x3.png": png(3, 3, 0, 8, gray8(3, 3)),
    "gray1_9x2.png": png(9, 2, 0, 1, [b"\xa5\x80", b"\x5a\x00"]),
    "rgb8_3x3.png": png(3, 3, 2, 8, [bytes(range(y * 9, y * 9 + 9)) for y in range(3)]),
    "rgba16_2x2.png": png(2, 2, 6, 16, [bytes(range(16)), bytes(range(16, 32))]),
    "gray_alpha8_2x2.png": png(2, 2, 4, 8, [b"\x10\xff\x20\x80", b"\x30\x00\x40\x7f"]),
    "palette_3x3.png": png(3, 3, 3, 8, [b"\0\1\2", b"\2\1\0", b"\1\1\1"], palette=b"\0\0\0\x80\x80\x80\xff\xff\xff",
                           trns=b"\xff\x80"),
    "interlaced16_5x5.png": png(5, 5, 0, 16, gray16(5, 5), interlace=1),
    "bad_range_text.png": png(3, 3, 0, 16, gray16(3, 3), {"fracterra:min": "nan", "fracterra:max": "-1e400"}),
    "truncated.png": png(5, 5, 0, 16, gray16(5, 5))[:60],
    "huge_header.png": png(1 << 20, 1 << 20, 0, 16, gray16(2, 2)),
    "zero_width.png": png(0, 4, 0, 8, gray8(1, 4)),
}
# A stored (uncompressed) 9 x 9 grid is the reference a terrain refines.
ref16 = png(9, 9, 0, 16, gray16(9, 9), {"fracterra:min": "0", "fracterra:max": "100"})
pngs["reference_9x9.png"] = ref16
for k, v in pngs.items():
    put("png", k, v)

# ---------------------------------------------------------------- PGM
pgms = {
    "p5_16_range.pgm": b"P5\n# fracterra-range -1 3\n3 2\n65535\n" + b"".join(struct.pack(">H", v) for v in (0, 1000, 65535, 3, 4, 5)),
    "p5_8.pgm": b"P5 4 2 255\n" + bytes(range(0, 80, 10)),
    "p2_plain.pgm": b"P2\n# comment\n3 3\n15\n0 1 2\n3 4 5\n6 7 15\n",
    "p2_exceeds_maxval.pgm": b"P2 2 1 3 1 9\n",
    "p5_truncated.pgm": b"P5 100 100 65535\n\0\0",
    "p5_huge.pgm": b"P5 1048576 1048576 255\n\0",
    "p5_zero_maxval.pgm": b"P5 2 2 0\n\0\0\0\0",
    "p2_long_number.pgm": b"P2 1 1 65535 123456789012\n",
    "comment_no_newline.pgm": b"P5 # fracterra-range 0",
}
for k, v in pgms.items():
    put("pgm", k, v)


# ---------------------------------------------------------------- NPY
def npy(arr, version=1, fortran=False):
    b = io.BytesIO()
    np.lib.format.write_array(b, np.asfortranarray(arr) if fortran else arr, version=(version, 0))
    return b.getvalue()


grid = np.arange(25, dtype=np.float32).reshape(5, 5) / 7.0
npys = {
    "f4_5x5.npy": npy(grid),
    "f8_3x4.npy": npy(np.linspace(-1, 1, 12).reshape(3, 4)),
    "i2_2x3.npy": npy(np.array([[-5, 0, 7], [1, 2, 32767]], dtype=np.int16)),
    "u1_2x2.npy": npy(np.array([[0, 255], [7, 9]], dtype=np.uint8)),
    "u8_2x2.npy": npy(np.array([[0, 2**64 - 1], [7, 9]], dtype=np.uint64)),
    "fortran_f4_2x3.npy": npy(np.arange(6, dtype=np.float32).reshape(2, 3), fortran=True),
    "v2_f4_3x3.npy": npy(np.ones((3, 3), dtype=np.float32), version=2),
    "1d_f4_9.npy": npy(np.linspace(0, 1, 9).astype(np.float32)),
    "3d.npy": npy(np.zeros((2, 2, 2), dtype=np.float32)),
    "big_endian.npy": npy(np.ones((2, 2), dtype=">f4")),
    "complex.npy": npy(np.ones((2, 2), dtype=np.complex64)),
    "short_data.npy": npy(np.ones((4, 4), dtype=np.float32))[:-8],
    "zero_dim.npy": npy(np.zeros((0, 3), dtype=np.float32)),
    "nan_inf.npy": npy(np.array([[np.nan, np.inf], [-np.inf, 1]], dtype=np.float32)),
}
for k, v in npys.items():
    put("npy", k, v)

# ---------------------------------------------------------------- polylines
csvs = {
    "two_lines.csv": "# x,y,z,radius\n0,0,0,1\n1,0.5,0,0.5\n\n2,2,2,0\n3,3,3,0.25\n",
    "xy_only.csv": "0,0\n1e-300,-1e300\r\n  2 , 3\n",
    "bad_nan.csv": "0,0,0\nnan,1,2\n",
    "bad_fields.csv": "1,2,3,4,5\n",
    "hex_and_blank.csv": "\n\n0x1p3,1\n\n\n# c\n4,5,6\n",
    "trailing_garbage.csv": "1,2,3x\n",
}
for k, v in csvs.items():
    put("polyline_csv", k, v)
jsons = {
    "two_lines.json": json.dumps({"polylines": [{"points": [[0, 0, 0], [1, 2, 3]], "radii": [1, 0.5]},
                                                {"points": [[4, 5], [6, 7]]}]}),
    "empty.json": '{"polylines": []}',
    "bad_radii.json": '{"polylines": [{"points": [[0, 0]], "radii": [1, 2]}]}',
    "bad_point.json": '{"polylines": [{"points": [[0]]}]}',
    "strings.json": '{"polylines": [{"points": [["1", 2]]}]}',
    "huge_int.json": '{"polylines": [{"points": [[18446744073709551615, -9223372036854775808, 1e400]]}]}',
    "deep.json": "[" * 200 + "]" * 200,
    "not_object.json": "[1, 2, 3]",
}
for k, v in jsons.items():
    put("polyline_json", k, v)

# ---------------------------------------------------------------- reference grids
# byte 0: format (0 png, 1 pgm, 2 npy, 3 1D npy -> profile); byte 1: knobs.
put("reference_grid", "png_9x9_levels3", bytes([0, 0x20]) + ref16)
put("reference_grid", "png_9x9_additions_periodic", bytes([0, 0x23]) + ref16)
put("reference_grid", "pgm_3x3_mean", bytes([1, 0x14]) + pgms["p2_plain.pgm"])
put("reference_grid", "npy_5x5_std", bytes([2, 0x38]) + npys["f4_5x5.npy"])
put("reference_grid", "npy_not_square", bytes([2, 0x30]) + npys["f8_3x4.npy"])
put("reference_grid", "npy_profile_9", bytes([3, 0x10]) + npys["1d_f4_9.npy"])
put("reference_grid", "npy_periodic_grid", bytes([2, 0x12]) + npy(np.zeros((3, 3), dtype=np.float32)))
put("reference_grid", "npy_nan_grid", bytes([2, 0x10]) + npys["nan_inf.npy"])


# ---------------------------------------------------------------- OBJ meshes
# byte 0: fractalize knobs (levels, scheme, mode, fix_boundary, scale_by_edge_length).
objs = {
    "cube_creases.obj": (0x00, "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                               "t crease 2/1/0 0 1 3\nt corner 1/1/0 6 10\n"),
    "tetra_loop.obj": (0x05, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"),
    "open_quad.obj": (0x21, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"),
    "bad_index.obj": (0x00, "v 0 0 0\nv 1 0 0\nf 1 2 9\n"),
    "zero_area.obj": (0x00, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
    "negative_and_slashes.obj": (0x00, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -3\nf 1/1/1 2//2 3/3\n"),
    "nan_vertex.obj": (0x00, "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
    "non_manifold.obj": (0x00, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 2 3\n"),
}
for k, (knobs, text) in objs.items():
    put("obj", k, bytes([knobs]) + text.encode())

# ---------------------------------------------------------------- C ABI params
# The params structs as the library describes them (fracterra/params.h): the
# add-on's ctypes binding builds them from the loaded library
# (FRACTERRA_LIBRARY, else build/native/libfracterra.so), so this file keeps
# no copy of their layout; ft_*_params_init gives the defaults.
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "blender_addon"))
os.environ.setdefault("FRACTERRA_LIBRARY", os.path.join(ROOT, "build", "native", "libfracterra.so"))
from fracterra.core.binding import library  # noqa: E402

LIB = library()


def initialised(kind, **kw):
    p = getattr(LIB, f"{kind}_params_type")()
    LIB.check(getattr(LIB, f"ft_{kind}_params_init")(ctypes.byref(p)))
    for k, v in kw.items():
        setattr(p, k, v)
    return p


def terrain(**kw):
    return initialised("terrain", **{"levels": 4, "width": 9, "height": 9, **kw})


def profile(**kw):
    return initialised("profile", **{"levels": 6, **kw})


# Layout of an input: [which: even = terrain, odd = profile] [struct bytes]
# [fixups: 1 = set struct_size, 2 = buffer one short (profile) or a falloff mask (terrain), 4 = NULL dst]
# [flags: 1 = reference, 2 = progress] [cancel after N reports] [reference floats...] [mask floats...]
def capi(name, which, params, fixups=1, flags=0, cancel=0, ref=(), mask=()):
    put("capi_params", name, bytes([which]) + bytes(params) + bytes([fixups, flags, cancel]) +
        b"".join(struct.pack("<f", v) for v in ref) + b"".join(struct.pack("<f", v) for v in mask))


capi("terrain_default", 0, terrain())
capi("terrain_additions_periodic", 0, terrain(method=1, periodic=1, threads=2))
capi("terrain_fbm_ridged_warp", 0, terrain(method=2, width=33, height=17, variant=1, warp=2.0))
capi("terrain_fbm_cellular", 0, terrain(method=2, width=20, height=20, basis=4, octaves=3))
capi("terrain_spectral", 0, terrain(method=3, width=32, height=24))
capi("terrain_interpolated", 0, terrain(method=4, width=40, height=40, lacunarity=3.0))
capi("terrain_abi_1_0_size", 0, terrain(struct_size=LIB.terrain_params_type.world_size.offset), fixups=0)
capi("terrain_too_large", 0, terrain(levels=12))
capi("terrain_nan_hurst", 0, terrain(hurst=float("nan")))
capi("terrain_struct_size_0", 0, terrain(struct_size=0), fixups=0)
capi("terrain_cancel_at_2", 0, terrain(levels=6), flags=2, cancel=2)
capi("terrain_reference_3", 0, terrain(reference_size=3, reference_scale=1), flags=1, ref=[1, 2, 3, 4, 5, 6, 7, 8, 9])
capi("terrain_reference_bad_size", 0, terrain(reference_size=4), flags=1, ref=[0] * 16)
capi("terrain_falloff_mask", 0, terrain(falloff=3, falloff_mask_width=3, falloff_mask_height=2), fixups=3,
     mask=[0, 0.5, 1, 1, 0.25, 0])
capi("terrain_falloff_mask_nan", 0, terrain(falloff=3, falloff_mask_width=2, falloff_mask_height=2), fixups=3,
     mask=[0, float("nan"), 1, 1])
capi("profile_default", 1, profile())
capi("profile_reference", 1, profile(reference_size=5, reference_scale=2), flags=3, cancel=9, ref=[0, 1, 0, -1, 0])
capi("profile_short_buffer", 1, profile(), fixups=3)
capi("profile_null_dst", 1, profile(), fixups=5)
capi("profile_levels_28", 1, profile(levels=28))


# Polyline and fractalize parameters. [which = 2 / 3] [struct] [fixups] ...
def polyline(**kw):
    return initialised("polyline", **{"depth": 6, "ifs_points": 1000, **kw})


def fractalize(**kw):
    return initialised("fractalize", **{"levels": 2, **kw})


def put_polyline(name, params, fixups=1, cancel=0, base=(), table=()):
    put("capi_params", name, bytes([2]) + bytes(params) + bytes([fixups]) +
        b"".join(struct.pack("<d", v) for v in base) + b"".join(struct.pack("<d", v) for v in table) +
        bytes([cancel]))


put_polyline("polyline_fpl", polyline())
put_polyline("polyline_lightning", polyline(branch_prob=0.8, method=1), fixups=17, cancel=3)
put_polyline("polyline_base", polyline(base_count=3), fixups=5, base=[0, 0, 0, 1, 0, 0, 1, 1, 0])
put_polyline("polyline_koch", polyline(method=2, depth=4))
put_polyline("polyline_ifs_table", polyline(method=5, ifs_maps=2), fixups=9,
             table=[0.5, 0, 0, 0.5, 0, 0, 1, 0.5, 0, 0, 0.5, 0.5, 0, 1])
put_polyline("polyline_profile", polyline(method=6, depth=10))
put_polyline("polyline_depth_40", polyline(depth=40))
put("capi_params", "fractalize_cube", bytes([3]) + bytes(fractalize()) + bytes([1]) + bytes(32) + bytes([0]))
put("capi_params", "fractalize_weights_cancel", bytes([3]) + bytes(fractalize(levels=3, mode=1, scheme=2)) +
    bytes([7]) + struct.pack("<8f", 1, 0, 0.5, 1, 1, 1, 0, 2) + bytes([1]))
put("capi_params", "fractalize_levels_10", bytes([3]) + bytes(fractalize(levels=10)) + bytes([1]) + bytes(33))


# Hurst and clouds parameters over a small heightfield: [which = 4 / 5] [struct]
# [fixups] [w - 4] [h - 4] [w * h floats].
def put_grid(name, which, params, fixups=1, w=9, h=9, values=None):
    z = values if values is not None else [((x * 7 + y * 13) % 11) * 0.25 for y in range(h) for x in range(w)]
    put("capi_params", name, bytes([which]) + bytes(params) + bytes([fixups, w - 4, h - 4]) +
        b"".join(struct.pack("<f", v) for v in z))


put_grid("hurst_aligned_9x9", 4, initialised("hurst"), fixups=5)
put_grid("hurst_auto_17x12", 4, initialised("hurst", method=5, transects=1), w=17, h=12)
put_grid("hurst_spectral_band", 4, initialised("hurst", method=4, freq_min=2, freq_max=3), w=20, h=20)
put_grid("hurst_nan_sample", 4, initialised("hurst"), values=[float("nan")] + [1.0] * 80)
put_grid("clouds_median", 5, initialised("clouds"))
put_grid("clouds_16bit_height", 5, initialised("clouds", bit_depth=16, threshold_is_quantile=0, threshold=1.0))
put_grid("clouds_short_buffer", 5, initialised("clouds"), fixups=3)
# ---------------------------------------------------------------- erosion (ft_erode)
# [w - 3] [h - 3] [flags: 1 periodic, 2 raw floats, 4 maps, 8 uplift follows, 16 two threads]
# [fluvial] [hydraulic] [thermal] [13 rate selectors, 0 = default] [world] [scale] [heights].
def erosion(w, h, flags, fluvial, hydraulic, thermal, heights, selectors=bytes(13), world=0, scale=128):
    fmt = "<%df" % len(heights) if flags & 2 else "<%dh" % len(heights)
    return bytes([w - 3, h - 3, flags, fluvial, hydraulic, thermal]) + selectors + bytes([world, scale]) + \
        struct.pack(fmt, *heights)


def bumps(w, h, amp):
    return [int(amp * (((x * 7 + y * 13) % 11) + ((x - w // 2) ** 2 + (y - h // 2) ** 2 < w * h // 8) * 8))
            for y in range(h) for x in range(w)]


put("capi_erosion", "land_17x17", erosion(17, 17, 4, 8, 8, 4, bumps(17, 17, 100)))
put("capi_erosion", "valleys_33x20_uplift", erosion(33, 20, 8, 16, 0, 0, bumps(33, 20, 50),
                                                    selectors=bytes([0, 0, 0, 0, 72] + [0] * 8)))
put("capi_erosion", "periodic_two_threads_16x16", erosion(16, 16, 1 | 16 | 4, 6, 6, 6, bumps(16, 16, 30)))
put("capi_erosion", "rain_raw_floats_9x9", erosion(9, 9, 2, 0, 16, 0, [((x * y) % 5) * 0.3 for y in range(9)
                                                                       for x in range(9)]))
put("capi_erosion", "plain_at_zero_3x3", erosion(3, 3, 0, 4, 0, 4, [0] * 9))
# Issue 25: 65 x 65 zeros with +1e38 at (20, 20) and -1e38 at (40, 40), 60 fluvial steps (it hung).
big = [0.0] * (40 * 65 + 41)
big[20 * 65 + 20], big[40 * 65 + 40] = 1e38, -1e38
regressions = os.path.join(HERE, "regressions", "capi_erosion")
os.makedirs(regressions, exist_ok=True)
with open(os.path.join(regressions, "issue25_heights_1e38"), "wb") as f:
    f.write(erosion(65, 65, 2, 60, 0, 0, big))

# ---------------------------------------------------------------- RAW16 + sidecar
# [uint16 count of sample bytes] [samples] [sidecar JSON text].
def raw16(samples, sidecar):
    data = b"".join(struct.pack("<H", v) for v in samples)
    return struct.pack("<H", len(data)) + data + sidecar.encode()


put("raw16", "3x2_range", raw16(range(0, 60000, 10000),
                                json.dumps({"format": "raw16", "width": 3, "height": 2, "min": -1.5, "max": 2.5,
                                            "world_size": 10})))
put("raw16", "square_no_sidecar", raw16([1, 2, 3, 4, 5, 6, 7, 8, 9], ""))
put("raw16", "huge_range", raw16([0, 65535], json.dumps({"width": 2, "height": 1, "min": -1e308, "max": 1e308})))
put("raw16", "size_mismatch", raw16([1, 2, 3], json.dumps({"width": 2, "height": 2})))
put("raw16", "not_json", raw16([1], "{width: 1"))

# ---------------------------------------------------------------- tile-set manifest
# manifest.json text, NUL, journal text.
def manifest(columns=2, rows=1, tile=64, complete=True):
    tiles = [{"column": c, "row": r, "file": "tile_%d_%d.npy" % (c, r), "x0": c * tile, "y0": r * tile,
              "width": tile + 1, "height": tile + 1, "crc32": None} for r in range(rows) for c in range(columns)]
    return json.dumps({"format": "fracterra-tileset", "version": 1, "terrain": {"method": "midpoint", "seed": 1},
                       "tile": tile, "tile_format": "npy", "width": columns * tile + 1, "height": rows * tile + 1,
                       "columns": columns, "rows": rows, "sample_spacing": 0.1, "world_size": [12.8, 6.4],
                       "height_range": {"min": -1, "max": 1, "how": "exact"}, "complete": complete,
                       "tiles": tiles}, indent=1)


put("manifest", "complete_2x1", manifest())
put("manifest", "journal", manifest(complete=False) + "\0" +
    '{"column":1,"row":0,"crc32":123}\n{"column":9,"row":0,"crc32":1}\n{"column":0,"ro')
put("manifest", "tiles_not_objects", manifest().replace('"tiles": [', '"tiles": [1, '))
put("manifest", "array", "[1, 2, 3]")
put("manifest", "terrain_a_number", manifest().replace('"terrain": {"method": "midpoint", "seed": 1}', '"terrain": 5'))

print("corpus written to", CORPUS)
