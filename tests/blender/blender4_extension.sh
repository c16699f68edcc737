#!/usr/bin/env bash
# The add-on zip in Blender 4.3 (Debian trixie's), as an artist installs it:
# `blender --command extension install-file --repo user_default --enable`, then
# the headless add-on tests (and Rivers and Lakes: its curves, bevel objects and
# meshes through 4.3's API; the comparison with the CLI is skipped there) and
# the planet's (its sea height against the CLI is skipped alike), inside a trixie root (scripts/blender4-root.sh)
# with no host libraries and no environment variables.
# Usage: blender4_extension.sh SOURCE_DIR ADDON_ZIP       (exit 77: skipped)
set -euo pipefail
src=$1 zip=$2
root=$("$src/scripts/blender4-root.sh") || exit $?
"$src/scripts/blender4-root.sh" --run "$root" \
  "$src/tests/blender:/ft/tests" "$(dirname "$zip"):/ft/zip" -- \
  sh -c "blender --command extension install-file --repo user_default --enable /ft/zip/$(basename "$zip") &&
         blender -b --python-exit-code 1 --python /ft/tests/test_addon.py -- --installed &&
         blender -b --python-exit-code 1 --python /ft/tests/test_rivers.py -- --installed &&
         blender -b --python-exit-code 1 --python /ft/tests/test_planet.py -- --installed"
