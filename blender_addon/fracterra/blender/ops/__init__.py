# SPDX-License-Identifier: GPL-3.0-or-later
"""The operators, one file per family: terrain, polyline, measure,
fractalize, POV-Ray export, DEM import/export, tile import. The top layer:
they import core, common/, build/ and ui/."""
