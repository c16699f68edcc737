"""Tile sets on Dask for a terrain larger than memory: `python3 -m fracterra.tiles
--levels 16 --tile 4096 --out DIR` (docs/scale.md). The driver is the add-on's
bpy-free fracterra.core.tiles, the one both packages carry; its tasks are
pickled by reference to that module, which every worker imports."""

from .core.tiles import (build_tileset, connect, exact_height_range, extent, main, manifest,  # noqa: F401
                         measure_tileset, read_window)

if __name__ == "__main__":
    import sys

    from fracterra.core import tiles as _tiles
    sys.exit(_tiles.main())
