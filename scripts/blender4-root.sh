#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds, or reuses, a Debian trixie root holding Debian's Blender 4.3, so the
# add-on zip can be tested in the Blender most artists run without touching
# the host. The root lives outside the repository (default
# /var/cache/fracterra/blender4-root) and is built once: a fresh machine
# spends about 3 minutes here, later runs none.
#
# Inside: blender, python3-numpy (blender.org bundles it, Debian packages it
# apart) and POV-Ray (the add-on's export renders with it). A root built with
# another package list is rebuilt.
# Usage: scripts/blender4-root.sh [ROOT]       prints ROOT when it is ready
#        scripts/blender4-root.sh --run ROOT BIND... -- CMD...
#            runs CMD inside ROOT in a private mount namespace with /proc, a
#            fresh /dev/shm, /tmp and /root (HOME) on tmpfs, and each
#            BIND=HOST:INSIDE folder mounted read-write, so the cached root is
#            never changed by a test.
# Needs root (debootstrap, chroot, mounts). Exit code 77 = cannot run here.
set -euo pipefail

# The Debian archive this machine's apt already uses: the first source of
# the host's own release (its suite is the codename: not -security or
# -updates), one-line (sources.list, *.list) or deb822 (*.sources), so the
# script works wherever apt works and names no host itself.
host_archive() {
  local codename files=()
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [ -f /etc/apt/sources.list ] && files+=(/etc/apt/sources.list)
  for f in /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do [ -f "$f" ] && files+=("$f"); done
  ((${#files[@]})) || return 1
  awk -v codename="$codename" '
    function take(uri) { sub(/\/+$/, "", uri); print uri; found = 1; exit }
    # One-line: deb [options] URI SUITE COMPONENTS...
    /^[ \t]*deb[ \t]/ {
      sub(/^[ \t]*deb[ \t]+/, ""); if ($0 ~ /^\[/) sub(/^\[[^]]*\][ \t]*/, "")
      split($0, f, /[ \t]+/); if (f[2] == codename) take(f[1]); next
    }
    # deb822: paragraphs of "Field: value" lines, blank lines between.
    /^[ \t]*$/ { if (types ~ /(^| )deb( |$)/ && (" " suites " ") ~ (" " codename " ")) { split(uris, u, / /); take(u[1]) }
                  types = uris = suites = ""; next }
    /^Types:/ { types = $0; sub(/^Types:[ \t]*/, "", types) }
    /^URIs:/ { uris = $0; sub(/^URIs:[ \t]*/, "", uris) }
    /^Suites:/ { suites = $0; sub(/^Suites:[ \t]*/, "", suites) }
    END { exit !found }
  ' < <(for f in "${files[@]}"; do cat "$f"; echo; done)  # a blank line ends each file's last paragraph
}
packages="blender python3-numpy povray povray-includes"
recipe="2 $packages"  # change the number when the steps below change

run_in_root() {
  local root=$1; shift
  local binds=()
  while (($#)) && [ "$1" != "--" ]; do binds+=("$1"); shift; done
  [ "${1:-}" = "--" ] && shift
  local setup="mount -t proc proc '$root/proc' && mount -t tmpfs tmpfs '$root/tmp'"
  setup+=" && mount -t tmpfs tmpfs '$root/root' && mkdir -p '$root/dev/shm' && mount -t tmpfs tmpfs '$root/dev/shm'"
  local b
  for b in "${binds[@]}"; do
    setup+=" && mkdir -p '$root${b#*:}' && mount --bind '${b%%:*}' '$root${b#*:}'"
  done
  # --pid --fork: the mounts and every process die with the command.
  unshare --mount --pid --fork --propagation private \
    sh -c "$setup && exec chroot '$root' /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \"\$@\"" \
    sh "$@"
}

if [ "${1:-}" = "--run" ]; then
  shift
  run_in_root "$@"
  exit
fi

root=${1:-/var/cache/fracterra/blender4-root}
if [ "$(id -u)" -ne 0 ]; then
  echo "blender4-root: needs root (debootstrap, chroot)" >&2
  exit 77
fi
for tool in debootstrap unshare chroot; do
  command -v "$tool" >/dev/null || { echo "blender4-root: $tool is missing (scripts/install-deps.sh test)" >&2; exit 77; }
done
mkdir -p "$(dirname "$root")"
# One builder at a time; the others wait and reuse its root.
exec 9>"$root.lock"
flock 9
if [ -x "$root/usr/bin/blender" ] && [ "$(cat "$root/.fracterra-recipe" 2>/dev/null)" = "$recipe" ]; then
  echo "$root"
  exit 0
fi
tmp="$root.tmp"
rm -rf "$tmp"
mirror=$(host_archive) ||
  { echo "blender4-root: no Debian archive of this release in /etc/apt/sources.list* to take trixie from" >&2; exit 77; }
start=$SECONDS
debootstrap --variant=minbase trixie "$tmp" "$mirror" >"$root.log" 2>&1 ||
  { echo "blender4-root: debootstrap failed, see $root.log" >&2; exit 1; }
# Blender lists mounted file systems from /etc/mtab (minbase has none).
ln -sf /proc/self/mounts "$tmp/etc/mtab"
run_in_root "$tmp" -- sh -c "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages" \
  >>"$root.log" 2>&1 || { echo "blender4-root: installing blender failed, see $root.log" >&2; exit 1; }
run_in_root "$tmp" -- apt-get clean
version=$(run_in_root "$tmp" -- blender --version | head -1)
echo "$recipe" >"$tmp/.fracterra-recipe"
rm -rf "$root"
mv "$tmp" "$root"
echo "blender4-root: built $root in $((SECONDS - start)) s ($version)" >&2
echo "$root"
