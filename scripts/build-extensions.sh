#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes one Blender extension per platform from the staged extension folder
# (blender_addon/CMakeLists.txt: the add-on, wheels/ with the native library,
# the manifest listing them) with Blender's own tools:
#   blender --command extension build --split-platforms   (fracterra-X-linux_x64.zip, -windows_x64.zip)
#   blender --command extension validate                  (each zip)
# by a Blender 4.2+ on PATH, else Debian trixie's 4.3 in the root that
# scripts/blender4-root.sh builds (needs root; exit 77 when neither is here).
# Usage: build-extensions.sh SOURCE_DIR EXTENSION_FOLDER OUT_DIR
set -euo pipefail
src=$1 folder=$(realpath "$2") out=$3
mkdir -p "$out"
out=$(realpath "$out")
rm -f "$out"/*.zip
commands="blender --command extension build --split-platforms --source-dir /ft/source --output-dir /ft/out &&
          for z in /ft/out/*.zip; do blender --command extension validate \"\$z\" || exit 1; done"
host_version=$(blender --version 2>/dev/null | sed -n 's/^Blender \([0-9]*\)\.\([0-9]*\).*/\1 \2/p' | head -1 || true)
if [ -n "$host_version" ] && { read -r major minor <<<"$host_version"; ((major > 4 || (major == 4 && minor >= 2))); }; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  ln -s "$folder" "$tmp/source" && ln -s "$out" "$tmp/out"
  sh -c "${commands//\/ft/$tmp}"
else
  root=$("$src/scripts/blender4-root.sh") || exit $?
  "$src/scripts/blender4-root.sh" --run "$root" "$folder:/ft/source" "$out:/ft/out" -- sh -c "$commands"
fi
ls -l "$out"/*.zip
