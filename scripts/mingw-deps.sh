#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the static mingw-w64 (Windows x64) libraries that fracterra.dll links
# and Debian ships no mingw package of: libpng and FFTW (float and double),
# from Debian's own source packages (`apt-get source`, verified by apt's
# signed indexes; Debian's patches applied), and GoogleTest for the tests.
# zlib is Debian's libz-mingw-w64-dev; the header-only libraries are staged
# by scripts/build-windows.sh.
#
# The result is cached outside the repository, keyed by the sources' versions
# and checksums, the build flags and the compiler, so a second run costs
# nothing (about 12 minutes of CPU the first time, FFTW nearly all of it):
#   ${XDG_CACHE_HOME:-~/.cache}/fracterra-mingw/<key>/{include,lib}
# Prints that prefix on its last line. Usage: scripts/mingw-deps.sh [--prefix]
set -euo pipefail
cd "$(dirname "$0")/.."
host=x86_64-w64-mingw32

# The Debian source versions (bookworm) and their upstream tarballs' sha256,
# checked after download; a newer Debian revision of the same upstream
# release is taken when the archive has one (a security fix).
png_pkg=libpng1.6 png_upstream=1.6.39
png_sha=a00e9d2f2f664186e4202db9299397f851aea71b36a35e74910b8820e380d441
fftw_pkg=fftw3 fftw_upstream=3.3.10
fftw_sha=56c932549852cddcfafdab3820b0200c7742675be92179e59e6215b340e26467

# FFTW's flags. -O2 as Debian's build. --with-our-malloc: the C runtime of
# Windows has no posix_memalign for the SIMD buffers. (FFTW's AVX codelets
# spill with unaligned moves already; tests/windows/check_dll.py checks the
# DLL for aligned 32-byte stack moves, see CMakeLists.txt.)
fftw_cflags="-O2"
fftw_flags="--disable-shared --enable-static --disable-fortran --disable-threads --disable-openmp --disable-doc
            --disable-dependency-tracking --with-our-malloc"
# Bump when the steps below change in a way the variables above do not show.
recipe=1
compiler=$($host-gcc-posix -dumpfullversion 2>/dev/null || $host-gcc-posix -dumpversion)
gtest=$(dpkg-query -W -f='${Version}' googletest)
key=$(echo "$recipe $png_upstream $png_sha $fftw_upstream $fftw_sha $fftw_cflags $fftw_flags $compiler $gtest" |
      sha256sum | cut -c1-12)
cache=${XDG_CACHE_HOME:-$HOME/.cache}/fracterra-mingw
prefix=$cache/$key
if [ "${1:-}" = "--prefix" ]; then  # where the result is (or will be), nothing built
  echo "$prefix"
  exit 0
fi
if [ -f "$prefix/.complete" ]; then
  echo "$prefix"
  exit 0
fi
jobs=$(nproc)
work=$(mktemp -d "$cache/work.XXXXXX" 2>/dev/null || { mkdir -p "$cache"; mktemp -d "$cache/work.XXXXXX"; })
trap 'rm -rf "$work"' EXIT
rm -rf "$prefix"
mkdir -p "$prefix/include" "$prefix/lib"
log() { echo "mingw-deps: $*" >&2; }

# apt-get source needs deb-src entries. They are derived at run time from
# this machine's own apt sources (whatever mirror it uses) into a private
# apt state, so the system's configuration is left as it was.
apt_src=$work/apt
mkdir -p "$apt_src/parts" "$apt_src/lists/partial"
: >"$apt_src/sources.list"
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] && sed -nE 's/^[[:space:]]*deb[[:space:]]+/deb-src /p' "$f" >>"$apt_src/sources.list"
done
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && sed -E 's/^Types:.*\bdeb\b.*/Types: deb-src/' "$f" >"$apt_src/parts/$(basename "$f")"
done
apt_opts=(-o "Dir::Etc::SourceList=$apt_src/sources.list" -o "Dir::Etc::SourceParts=$apt_src/parts"
          -o "Dir::State::Lists=$apt_src/lists" -o "APT::Sandbox::User=root")
log "reading the source indexes"
apt-get "${apt_opts[@]}" update -qq >&2

# Downloads and unpacks a source package into $work/$1-src: the newest
# Debian revision whose files the archive serves (a security suite may list a
# revision its mirror no longer has), checking the upstream tarball.
fetch_source() {
  local pkg=$1 upstream=$2 sha=$3 v
  local versions
  versions=$(apt-cache "${apt_opts[@]}" showsrc "$pkg" | sed -n 's/^Version: //p' | sort -Vru)
  for v in $versions; do
    case "$v" in "$upstream"-*) ;; *) continue ;; esac
    rm -rf "$work/dl" && mkdir -p "$work/dl"
    if (cd "$work/dl" && apt-get "${apt_opts[@]}" source --download-only -qq "$pkg=$v" >&2 2>/dev/null); then
      echo "$sha  $work/dl/${pkg}_$upstream.orig.tar.gz" | sha256sum -c --quiet - >&2 ||
        { log "$pkg $upstream: upstream tarball checksum mismatch"; exit 1; }
      (cd "$work/dl" && dpkg-source --no-check -x ./*.dsc "$work/$pkg-src" >/dev/null)
      log "$pkg $v"
      return 0
    fi
  done
  log "no source of $pkg $upstream could be downloaded (versions listed: $versions)"
  exit 1
}

fetch_source "$png_pkg" "$png_upstream" "$png_sha"
fetch_source "$fftw_pkg" "$fftw_upstream" "$fftw_sha"

# libpng: static, no tests or tools, against the sysroot's static zlib.
log "building libpng"
cmake -S "$work/$png_pkg-src" -B "$work/png-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/mingw-w64-x86_64.cmake" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DPNG_SHARED=OFF -DPNG_STATIC=ON -DPNG_TESTS=OFF -DPNG_EXECUTABLES=OFF \
  -DZLIB_LIBRARY=/usr/$host/lib/libz.a -DZLIB_INCLUDE_DIR=/usr/$host/include >/dev/null
cmake --build "$work/png-build" -j"$jobs" >/dev/null
cmake --install "$work/png-build" >/dev/null

# FFTW: the codelets Debian's amd64 build has (float: SSE + AVX, double: SSE2
# + AVX; no AVX2, so no FMA), so that FFTW_ESTIMATE picks the same plans and
# spectral terrains have the same bits as on Linux. Only the library itself:
# no Fortran, threads, documentation, bench or wisdom tool.
build_fftw() {
  local prec_flags=$1 simd_flags=$2 name=$3 dir=$work/fftw-$3
  log "building FFTW ($name)"
  cp -r "$work/$fftw_pkg-src" "$dir"
  # shellcheck disable=SC2086  # the flag lists split into words
  (cd "$dir" && ./configure -q --host=$host CC=$host-gcc-posix CFLAGS="$fftw_cflags" $prec_flags $simd_flags \
      $fftw_flags >/dev/null)
  # Compiles without libtool's per-file script (scripts/libtool-compile.sh:
  # the same objects and archives, 44 % less CPU), links with it.
  local libtool=(LIBTOOL="sh $PWD/scripts/libtool-compile.sh $dir/libtool")
  for d in support kernel simd-support dft rdft reodft api; do
    make -s -C "$dir/$d" -j"$jobs" "${libtool[@]}" >/dev/null
  done
  make -s -C "$dir" -j"$jobs" "${libtool[@]}" "lib$name.la" >/dev/null
  cp "$dir/.libs/lib$name.a" "$prefix/lib/"
  cp "$dir/api/fftw3.h" "$prefix/include/"
}
build_fftw "--enable-single" "--enable-sse --enable-avx" fftw3f &
fftw_f=$!
build_fftw "" "--enable-sse2 --enable-avx" fftw3
wait $fftw_f


# GoogleTest for the C ABI suites run under Wine, from Debian's googletest
# sources (/usr/src/googletest).
log "building GoogleTest"
cmake -S /usr/src/googletest -B "$work/gtest-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/mingw-w64-x86_64.cmake" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DBUILD_GMOCK=OFF -Dgtest_disable_pthreads=OFF >/dev/null
cmake --build "$work/gtest-build" -j"$jobs" >/dev/null
cmake --install "$work/gtest-build" >/dev/null

touch "$prefix/.complete"
echo "$prefix"
