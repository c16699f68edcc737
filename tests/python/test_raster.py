# SPDX-License-Identifier: GPL-3.0-or-later
"""Heightfield files and DEM refinement through the binding (core/raster.py),
checked against GDAL's own Python bindings."""

import array
import re

import pytest

osgeo = pytest.importorskip("osgeo", reason="python3-gdal (scripts/install-deps.sh installs it)")
from osgeo import gdal, osr  # noqa: E402

from fracterra.core import raster  # noqa: E402


def _utm_dem(path, w=40, h=30, holes=0):
    gdal.UseExceptions()
    ds = gdal.GetDriverByName("GTiff").Create(str(path), w, h, 1, gdal.GDT_Float32)
    ds.SetGeoTransform((500000, 25, 0, 5500000, 0, -25))
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(32632)
    ds.SetProjection(srs.ExportToWkt())
    band = ds.GetRasterBand(1)
    band.SetNoDataValue(-9999)
    values = array.array("f", [(x * 7 + y * 13) % 50 + 0.25 * x for y in range(h) for x in range(w)])
    for i in range(holes):
        values[i] = -9999
    band.WriteRaster(0, 0, w, h, values.tobytes())
    ds = None
    return values


def test_every_written_format_reads_back(core, tmp_path):
    with core.generate_terrain(levels=5, seed=3) as hf:
        want = hf.to_array()
        for ext in raster.WRITE_EXTENSIONS:
            path = tmp_path / f"t{ext}"
            raster.write_heightfield(hf, path)
            with raster.read_heightfield(path) as back:
                got = back.to_array()
            lo, hi = min(want), max(want)
            # float formats exact; 16-bit ones within half a step (plus float rounding)
            tol = 0 if ext in (".tif", ".exr", ".npy") else 0.5 * (hi - lo) / 65535 + 1e-6 * max(abs(lo), abs(hi))
            assert max(abs(a - b) for a, b in zip(want, got)) <= tol, ext


def test_a_generated_terrain_is_written_north_up_in_its_tile_sets_frame(core, tmp_path):
    # The frame tile sets use (pixel-is-area, sample (0, 0) centred on the
    # origin, rows going south): the whole and its tiles overlay in a GIS,
    # and rivers traced from either have the same sign of y.
    with core.generate_terrain(levels=5, seed=3) as hf:
        world = hf.world_size
        raster.write_heightfield(hf, tmp_path / "t.tif")
    s = world / 32
    gt = gdal.Open(str(tmp_path / "t.tif")).GetGeoTransform()
    assert gt == pytest.approx((-0.5 * s, s, 0.0, 0.5 * s, 0.0, -s), rel=1e-12, abs=1e-15)
    with raster.read_heightfield(tmp_path / "t.tif") as back:
        assert back.world_size == world  # exactly, not (width - 1) x a rounded pixel width
        raster.write_heightfield(back, tmp_path / "again.tif")
    assert gdal.Open(str(tmp_path / "again.tif")).GetGeoTransform() == gt


def test_georeference_survives_a_round_trip(tmp_path):
    _utm_dem(tmp_path / "dem.tif")
    with raster.read_heightfield(tmp_path / "dem.tif") as hf:
        assert hf.world_size == pytest.approx(39 * 25)
        raster.write_heightfield(hf, tmp_path / "out.tif")
    a, b = gdal.Open(str(tmp_path / "dem.tif")), gdal.Open(str(tmp_path / "out.tif"))
    assert b.GetGeoTransform() == a.GetGeoTransform()
    assert osr.SpatialReference(b.GetProjection()).IsSame(osr.SpatialReference(a.GetProjection()))
    assert b.GetMetadata("IMAGE_STRUCTURE")["LAYOUT"] == "COG"


def test_nodata_is_refused_with_its_count_or_filled(core, tmp_path):
    _utm_dem(tmp_path / "holes.tif", holes=5)
    with pytest.raises(core.FracterraError, match=re.escape("5 nodata samples of 1200")):
        raster.read_heightfield(tmp_path / "holes.tif")
    with raster.read_heightfield(tmp_path / "holes.tif", nodata="FILL") as hf:
        assert all(v == v and v > -9999 for v in hf.to_array())


def test_a_dem_refines_with_its_values_at_the_nodes(tmp_path):
    values = _utm_dem(tmp_path / "dem.tif", w=40, h=30, holes=3)
    with raster.read_heightfield(tmp_path / "dem.tif", nodata="KEEP") as dem:
        fine, report = raster.refine_dem(dem, levels_added=2, hurst=0.7)
        with fine:
            assert report["window_side"] == 17 and not report["hurst_measured"] and report["sigma_measured"]
            assert fine.width == 65
            got = fine.to_array()
            x0, y0 = report["window_x"], report["window_y"]
            for y in range(17):
                for x in range(17):
                    assert got[4 * y * 65 + 4 * x] == values[(y0 + y) * 40 + x0 + x]
            raster.write_heightfield(fine, tmp_path / "fine.tif")
    gt = gdal.Open(str(tmp_path / "fine.tif")).GetGeoTransform()
    assert gt[1] == pytest.approx(25 / 4)


def test_a_bad_file_is_a_clear_error(core, tmp_path):
    (tmp_path / "junk.tif").write_bytes(b"II*\x00" + b"\x00" * 20)
    with pytest.raises(core.FracterraError, match="junk.tif"):
        raster.read_heightfield(tmp_path / "junk.tif")
    with core.generate_terrain(levels=3) as hf:
        with pytest.raises(core.FracterraError, match="unsupported heightfield format"):
            raster.write_heightfield(hf, tmp_path / "t.bmp")
    assert not (tmp_path / "t.bmp").exists()
