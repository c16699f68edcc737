#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a Windows program under Wine for ctest:  tests/windows/wine_run.sh PROGRAM.exe ARGS...
# Exits 77 (the tests' SKIP_RETURN_CODE) with the reason on stdout when the
# program is missing or Wine cannot run here. The Wine prefix (about 10 s to
# make) lives outside the repository and is made once, under a lock, since
# ctest runs tests side by side. `wine_run.sh --prepare` only makes the
# prefix (tests/run.sh does, while the builds run, so that no test waits).
set -u
program=$1
shift
if [ "$program" != --prepare ]; then
  [ -f "$program" ] || { echo "SKIP: $program is missing: scripts/build-windows.sh makes the Windows build"; exit 77; }
fi
wine=""
for w in wine64 wine /usr/lib/wine/wine64; do
  if command -v "$w" >/dev/null 2>&1; then wine=$(command -v "$w"); break; fi
done
[ -n "$wine" ] || { echo "SKIP: Wine is not installed (scripts/install-deps.sh windows installs wine64)"; exit 77; }
export WINEPREFIX=${FT_WINEPREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/fracterra-wine}
# -all: no fixme lines in the tests' output; UTF-8: Wine turns our arguments
# into the wide command line by the locale's encoding.
export WINEDEBUG=-all LC_ALL=C.UTF-8
mkdir -p "$(dirname "$WINEPREFIX")"
(
  flock 9
  if [ ! -f "$WINEPREFIX/.fracterra-ready" ]; then
    if "$wine" cmd /c exit 0 >"$WINEPREFIX.log" 2>&1; then
      touch "$WINEPREFIX/.fracterra-ready"
    fi
  fi
) 9>"$WINEPREFIX.lock"
if [ ! -f "$WINEPREFIX/.fracterra-ready" ]; then
  echo "SKIP: Wine cannot run Windows programs here ($wine, prefix $WINEPREFIX):"
  tail -n 5 "$WINEPREFIX.log"
  exit 77
fi
[ "$program" != --prepare ] || exit 0
exec "$wine" "$program" "$@"
