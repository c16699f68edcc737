# SPDX-License-Identifier: GPL-3.0-or-later
"""The ctypes binding of libfracterra.so, outside Blender."""

import array
import ctypes
import re

import pytest


def test_library_reports_matching_abi_and_version(core):
    lib = core.library()
    assert lib.abi_major == 2
    assert re.fullmatch(r"\d+\.\d+\.\d+", lib.version)
    ok, message = core.status()
    assert ok and lib.version in message


def test_every_declared_symbol_has_argtypes_and_restype(core):
    from fracterra.core.binding import PARAMS_KINDS, SIGNATURES, _Described
    lib = core.library()
    for name, (restype, argtypes) in SIGNATURES.items():
        fn = getattr(lib, name)
        # A described struct's pointer type is made at load time from the library's table.
        argtypes = [ctypes.POINTER(lib.struct_types[PARAMS_KINDS[a.kind]]) if isinstance(a, _Described) else a
                    for a in argtypes]
        assert fn.argtypes == argtypes, name
        assert fn.restype == restype, name


def test_binding_declares_every_exported_function_of_its_headers(core, header_dir):
    # Every ft_ function declared in the headers the binding covers has a signature.
    from fracterra.core.binding import SIGNATURES
    for header in ("core.h", "terrain.h", "mesh.h", "polyline.h", "subdiv.h", "params.h", "raster.h", "splat.h",
                   "pipeline.h", "hydrology.h", "planet.h", "analysis.h"):
        text = (header_dir / header).read_text()
        for name in re.findall(r"FT_API [^(;]*?\b(ft_\w+)\s*\(", text):
            assert name in SIGNATURES, f"{name} from {header} has no ctypes signature"


def _struct_fields(header_text, struct):
    body = re.search(r"typedef struct %s \{(.*?)\} %s;" % (struct, struct), header_text, re.S).group(1)
    body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
    body = re.sub(r"//[^\n]*", "", body)
    return re.findall(r"(\w+)\s*(?:\[\d+\])?\s*;", body)


def test_ctypes_structs_follow_the_header_field_order(core, header_dir):
    from fracterra.core import binding as b
    from fracterra.core.binding import GridCounts
    lib = core.library()  # the params structs are built from the library's description
    for header, struct, cls in (("terrain.h", "ft_terrain_params", lib.terrain_params_type),
                                ("terrain.h", "ft_profile_params", lib.profile_params_type),
                                ("polyline.h", "ft_polyline_params", lib.polyline_params_type),
                                ("polyline.h", "ft_polyline_stats", b.PolylineStats),
                                ("analysis.h", "ft_hurst_params", lib.hurst_params_type),
                                ("analysis.h", "ft_clouds_params", lib.clouds_params_type),
                                ("analysis.h", "ft_hurst_result", b.HurstResult),
                                ("povray.h", "ft_pov_scene_lines", b.PovSceneLines),
                                ("povray.h", "ft_pov_light", b.PovLight),
                                ("povray.h", "ft_pov_material", b.PovMaterial),
                                ("povray.h", "ft_pov_scene_mesh", b.PovSceneMesh),
                                ("povray.h", "ft_pov_scene_params", lib.pov_scene_params_type),
                                ("povray.h", "ft_pov_sweep_params", lib.pov_sweep_params_type),
                                ("raster.h", "ft_dem_refine_params", lib.dem_refine_params_type),
                                ("splat.h", "ft_splat_params", lib.splat_params_type),
                                ("subdiv.h", "ft_fractalize_params", lib.fractalize_params_type),
                                ("pipeline.h", "ft_terrain_world", b.TerrainWorld),
                                ("polyline.h", "ft_fpl_study_row", b.FplStudyRow),
                                ("hydrology.h", "ft_network_measures", b.NetworkMeasures)):
        fields = _struct_fields((header_dir / header).read_text(), struct)
        fields = [f.split("[")[0] for f in fields]
        assert [f for f, _ in cls._fields_] == fields, struct
    assert [f for f, _ in GridCounts._fields_][:4] == ["vertices", "edges", "faces", "loops"]


def test_parameter_enums_match_the_header_values(core, header_dir):
    text = (header_dir / "terrain.h").read_text()
    values = {name: int(v) for name, v in re.findall(r"(FT_\w+)\s*=\s*(\d+)", text)}
    p = core.params.PARAMS_BY_NAME
    prefixes = {"method": "FT_TERRAIN_", "basis": "FT_BASIS_", "variant": "FT_FBM_",
                "reference_scale": "FT_REFSCALE_"}
    for name, prefix in prefixes.items():
        for ident, _label, _tip, number in p[name].items:
            assert values[prefix + ident] == number, (name, ident)
    text = (header_dir / "polyline.h").read_text()
    values = {name: int(v) for name, v in re.findall(r"(FT_\w+)\s*=\s*(\d+)", text)}
    q = {x.name: x for x in core.params.POLYLINE_PARAMS}
    for name, prefix in {"method": "FT_POLYLINE_", "rng": "FT_POLYLINE_RNG_", "ifs_preset": "FT_IFS_"}.items():
        for ident, _label, _tip, number in q[name].items:
            assert values[prefix + ident] == number, (name, ident)


def test_every_c_field_parameter_names_a_struct_field(core):
    fields = {f for f, _ in core.library().terrain_params_type._fields_}
    for p in core.params.TERRAIN_PARAMS:
        if p.field:
            assert p.field in fields, p.name


def test_terrain_has_dyadic_size_and_is_deterministic(core):
    with core.generate_terrain(levels=5, seed=42, hurst=0.7) as a, \
            core.generate_terrain(levels=5, seed=42, hurst=0.7, threads=1) as b, \
            core.generate_terrain(levels=5, seed=43, hurst=0.7) as c:
        assert (a.width, a.height) == (33, 33)
        assert a.to_array().tobytes() == b.to_array().tobytes()
        assert a.to_array().tobytes() != c.to_array().tobytes()


def test_additions_differs_from_midpoint(core):
    with core.generate_terrain(method="MIDPOINT", levels=4, seed=1) as m, \
            core.generate_terrain(method="ADDITIONS", levels=4, seed=1) as a:
        assert m.to_array() != a.to_array()


def test_sigma_scales_the_terrain_linearly(core):
    # sigma multiplies every displacement: the same seed at sigma 2 is exactly twice sigma 1
    # (a power of two keeps float rounding exact).
    with core.generate_terrain(levels=4, seed=9, sigma=1.0) as a, core.generate_terrain(levels=4, seed=9, sigma=2.0) as b:
        assert [2 * x for x in a.to_array()] == list(b.to_array())


def test_bad_hurst_raises_with_the_library_message(core):
    with pytest.raises(core.InvalidArgumentError, match=r"hurst must be in \[0, 1\], got 1.5"):
        core.generate_terrain(hurst=1.5)


def test_bad_levels_raise_invalid_argument(core):
    with pytest.raises(core.InvalidArgumentError, match="levels"):
        core.generate_terrain(levels=0)


def test_every_method_generates_its_grid(core):
    for ident, *_ in core.params.PARAMS_BY_NAME["method"].items:
        with core.generate_terrain(method=ident, levels=4, width=20, height=12, seed=3) as hf:
            side = 2 ** 4 + 1
            expected = (side, side) if ident in core.params.DYADIC_METHODS else (20, 12)
            assert (hf.width, hf.height) == expected, ident
            assert hf.stats()["std"] > 0, ident


def test_mandelbrot_view_and_its_level_height(core):
    # The default view holds c = 0 (inside: the plateau, the highest sample)
    # and the corner -2.5 + 2i (outside, lower).
    with core.generate_terrain(method="MANDELBROT", width=65, height=65, zoom=1.0, iterations=40) as hf:
        h = hf.to_array()
        assert h[32 * 65 + 40] == max(h)  # c = 0: column 32 + 0.5 / (4 / 64) = 40
        assert h[0] < h[32 * 65 + 40]


def test_reference_values_survive_at_their_nodes(core):
    ref = [float(i % 7) - 3.0 for i in range(25)]  # 5 x 5 = levels 2 reference
    with core.generate_terrain(levels=4, seed=5, reference=(5, ref)) as hf:
        h = hf.to_array()
        step = (hf.width - 1) // 4
        for j in range(5):
            for i in range(5):
                assert h[j * step * hf.width + i * step] == ref[j * 5 + i]


def test_bad_reference_size_is_reported(core):
    with pytest.raises(core.InvalidArgumentError, match="reference_size"):
        core.generate_terrain(levels=2, reference=(9, [0.0] * 81))


def test_progress_reaches_one_and_can_cancel(core):
    seen = []
    with core.generate_terrain(levels=6, progress=lambda f: seen.append(f) or False):
        pass
    assert seen and seen == sorted(seen) and seen[-1] == pytest.approx(1.0)
    with pytest.raises(core.CancelledError):
        core.generate_terrain(levels=6, progress=lambda f: f > 0.3)


def test_exception_in_progress_callback_cancels_and_is_reraised(core):
    def boom(_fraction):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        core.generate_terrain(levels=6, progress=boom)


def test_heightfield_context_manager_releases_the_handle(core):
    with core.generate_terrain(levels=3) as hf:
        assert hf.handle
    assert hf.handle is None
    hf.close()  # twice is harmless


def test_heightfield_stats_match_the_samples(core):
    with core.generate_terrain(levels=5, seed=2) as hf:
        h = hf.to_array()
        s = hf.stats()
    assert s["min"] == min(h) and s["max"] == max(h)
    assert s["mean"] == pytest.approx(sum(h) / len(h), rel=1e-6, abs=1e-9)


def test_writes_through_data_mut_are_what_the_library_sees(core):
    # ft_heightfield_data_mut lets a host edit a library heightfield in place (no
    # copy back): copy, stats and every later call see the edit.
    lib = core.library()
    with core.Heightfield.from_values(2, 2, [0.0, 1.0, 2.0, 3.0]) as hf:
        p = lib.ft_heightfield_data_mut(hf.handle)
        assert ctypes.cast(p, ctypes.c_void_p).value == ctypes.cast(lib.ft_heightfield_data(hf.handle),
                                                                    ctypes.c_void_p).value
        p[3] = 10.0
        assert list(hf.to_array()) == [0.0, 1.0, 2.0, 10.0]
        assert hf.stats()["max"] == 10.0
    assert not lib.ft_heightfield_data_mut(None)


def test_profile_has_2_to_the_levels_plus_one_samples(core):
    a = core.generate_profile(levels=8, seed=4)
    assert len(a) == 257 and a == core.generate_profile(levels=8, seed=4)
    with pytest.raises(core.InvalidArgumentError, match="levels"):
        core.generate_profile(levels=0)


def test_terrain_side(core):
    assert core.terrain_side(10) == 1025
    assert core.terrain_side(0) == -1


def test_missing_library_gives_instructions(monkeypatch, tmp_path):
    from fracterra.core import binding as lib_mod
    saved = lib_mod._library
    monkeypatch.setenv("FRACTERRA_LIBRARY", str(tmp_path / "nope.so"))
    lib_mod.reset()
    try:
        with pytest.raises(lib_mod.LibraryNotFoundError, match="FRACTERRA_LIBRARY=.*nope.so.*does not exist"):
            lib_mod.library()
        ok, message = lib_mod.status()
        assert not ok and "fracterra_blender_addon" in message
    finally:
        lib_mod._library = saved


def test_a_file_that_is_not_a_library_is_refused(monkeypatch, tmp_path):
    from fracterra.core import binding as lib_mod
    bogus = tmp_path / "libfracterra.so"
    bogus.write_bytes(b"not an ELF file")
    saved = lib_mod._library
    monkeypatch.setenv("FRACTERRA_LIBRARY", str(bogus))
    lib_mod.reset()
    try:
        with pytest.raises(lib_mod.LibraryNotFoundError, match="cannot load"):
            lib_mod.library()
    finally:
        lib_mod._library = saved


def test_params_structs_are_sized_by_the_library(core):
    lib = core.library()
    for struct_type, init in ((lib.terrain_params_type, lib.ft_terrain_params_init),
                              (lib.profile_params_type, lib.ft_profile_params_init)):
        p = struct_type()
        lib.check(init(ctypes.byref(p)))
        assert p.struct_size == ctypes.sizeof(p)


def test_world_size_reaches_the_heightfield(core):
    with core.generate_terrain(levels=3, world_size=42.0) as hf:
        assert hf.world_size == 42.0
    with pytest.raises(core.InvalidArgumentError, match="world_size"):
        core.generate_terrain(levels=3, world_size=0.0)


def test_custom_falloff_mask_from_python_sequences_and_numpy(core):
    np = pytest.importorskip("numpy")
    with core.generate_terrain(levels=4, seed=2, edge_level=-1.0) as raw:
        z = raw.to_array()
    mask = (2, 2, [0.0, 1.0, 1.0, 1.0])  # black at row 0, column 0
    for given in (mask, (2, 2, np.array(mask[2], dtype=np.float32))):
        with core.generate_terrain(levels=4, seed=2, edge_level=-1.0, falloff="CUSTOM", falloff_mask=given) as hf:
            got = hf.to_array()
        assert got[0] == -1.0  # weight 0: the edge level
        assert got[16 * 17 + 16] == z[16 * 17 + 16]  # weight 1: the height
    with pytest.raises(core.InvalidArgumentError, match="falloff mask has 3 values"):
        core.generate_terrain(levels=4, falloff="CUSTOM", falloff_mask=(2, 2, [0.0, 1.0, 1.0]))
    with pytest.raises(core.InvalidArgumentError, match=r"must be in \[0, 1\]"):
        core.generate_terrain(levels=4, falloff="CUSTOM", falloff_mask=(2, 2, [0.0, 1.0, 2.0, 1.0]))
    with pytest.raises(core.InvalidArgumentError, match="needs a mask"):
        core.generate_terrain(levels=4, falloff="CUSTOM")


def test_an_unsupported_platform_is_named(monkeypatch):
    """The zip carries Linux and Windows x64 libraries; elsewhere the error names the platform
    (with the check removed, the message was "libfracterra.so not found ... does not exist")."""
    from fracterra.core import binding as lib_mod
    saved = lib_mod._library
    monkeypatch.delenv("FRACTERRA_LIBRARY", raising=False)
    monkeypatch.setattr(lib_mod, "PLATFORM", ("darwin", "arm64"))
    monkeypatch.setattr(lib_mod.sys, "platform", "darwin")
    monkeypatch.setattr(lib_mod.platform, "machine", lambda: "arm64")
    lib_mod.reset()
    try:
        with pytest.raises(lib_mod.LibraryNotFoundError,
                           match=r"no library for this platform \(darwin, arm64\).*fracterra\.dll for x64 Windows"):
            lib_mod.library()
    finally:
        lib_mod._library = saved


def test_each_platform_loads_its_own_file():
    from fracterra.core import binding as lib_mod
    assert lib_mod.LIBRARY_NAMES[("linux", "x86_64")] == "libfracterra.so"
    assert lib_mod.LIBRARY_NAMES[("win32", "amd64")] == "fracterra.dll"  # platform.machine() is "AMD64" there


def test_the_build_says_what_it_has(core):
    lib = core.library()
    features = lib.ft_build_features().decode().split()
    assert set(features) <= {"gdal", "openexr", "opensubdiv"}
    for name in ("gdal", "openexr", "opensubdiv"):
        assert lib.ft_has_feature(name.encode()) == (name in features)
    assert lib.ft_has_feature(b"") == 0 and lib.ft_has_feature(b"gdal openexr") == 0 and lib.ft_has_feature(None) == 0
    assert "PNG, PGM, NPY" in lib.ft_heightfield_formats().decode()
