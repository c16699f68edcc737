#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The real DEM of the raster tests: elev.tif of Debian's r-cran-terra
# (Luxembourg, 95 x 90 samples of 30 arc-seconds, SRTM-derived elevation in
# metres, WGS 84, with nodata outside the country). The package is only
# downloaded and unpacked (apt-get download + dpkg-deb -x), not installed, so
# R is not pulled in. Usage: fetch_dem.sh DEST_DIR  ->  DEST_DIR/elev.tif
set -euo pipefail
dest=$1
want=c6a4967fe5b720499e75a3453e9814f00a416167b8e0926a4c55f5100ae4ddb2
if [ -f "$dest/elev.tif" ] && echo "$want  $dest/elev.tif" | sha256sum -c --status; then exit 0; fi
mkdir -p "$dest"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! apt-get download r-cran-terra >/dev/null 2>&1; then
  # A fresh machine may have no package lists yet.
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  apt-get download r-cran-terra >/dev/null
fi
dpkg-deb -x r-cran-terra_*.deb x
cp x/usr/lib/R/site-library/terra/ex/elev.tif "$dest/elev.tif.part"
if ! echo "$want  $dest/elev.tif.part" | sha256sum -c --status; then
  echo "fetch_dem.sh: elev.tif of this r-cran-terra is not the one the tests were written for" >&2
  echo "  (sha256 $(sha256sum "$dest/elev.tif.part" | cut -d' ' -f1)); update the expected values" >&2
  exit 1
fi
mv "$dest/elev.tif.part" "$dest/elev.tif"
