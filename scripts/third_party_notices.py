# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes THIRD_PARTY_NOTICES for what a package carries: every bundled shared
library, every static archive linked into fracterra's library and every
header-only library compiled into it, each with its Debian package, that
package's licences and its copyright file (/usr/share/doc/PKG/copyright,
which Debian requires to hold the full licence texts).

Run by the bundling step (blender_addon/CMakeLists.txt, python/CMakeLists.txt)
with what it just bundled, so the notices cannot go stale:

    python3 third_party_notices.py OUT
        --bundled LIST                 the bundled shared libraries: lines "NAME SOURCE-PATH"
                                       (blender_addon/bundle_libs.cmake's RECORD)
        --link-map FILE                a linker map (-Wl,-Map): the static archives it pulled members from
        --compiled-in FILE...          headers of header-only libraries compiled in
        --windows-map FILE             the map of fracterra.dll's link, when the package carries it

A file is mapped to its package by `dpkg -S`. The mingw-w64 static archives
that scripts/mingw-deps.sh builds from Debian's source packages are not
installed files: they are named after the Debian package of the same source
(MINGW_BUILT). A file no package owns fails the run: its licence would be
unknown. tests/blender/check_notices.py compares a package's files with the
notices.
"""

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

# Archives scripts/mingw-deps.sh builds from Debian source packages (not
# installed by dpkg): the binary package of the same source on this machine.
MINGW_BUILT = {"libpng16.a": "libpng-dev", "libpng.a": "libpng-dev", "libfftw3f.a": "libfftw3-dev",
               "libfftw3.a": "libfftw3-dev"}
# glibc (and the dynamic loader) are the system's, never carried.
SYSTEM_PACKAGES = {"libc6", "libc6-dev"}


def owner(path):
    """The Debian package that installed `path` (tried as given, resolved, and
    with /usr and / swapped for merged-/usr systems), or None."""
    p = str(path)
    tries = [p, os.path.realpath(p)]
    for t in list(tries):
        tries.append(t[4:] if t.startswith("/usr/") else "/usr" + t)
    for t in tries:
        r = subprocess.run(["dpkg", "-S", t], capture_output=True, text=True)
        if r.returncode == 0:
            line = r.stdout.splitlines()[0]
            return line.split(":")[0].split(",")[0].strip()
    return None


def version(package):
    r = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 else "?"


def copyright_text(package):
    path = Path("/usr/share/doc", package, "copyright")
    return path.read_text(encoding="utf-8", errors="replace") if path.is_file() else None


# Free-form copyright files (no DEP-5 fields) whose licence a phrase names.
FREE_FORM = [("GCC RUNTIME LIBRARY EXCEPTION", "GPL-3+ with the GCC Runtime Library Exception 3.1")]


def licences(text):
    """The licence names of a machine-readable (DEP-5) copyright file's Files
    paragraphs, in order; for a free-form one, what FREE_FORM recognises ([] else)."""
    if not text:
        return []
    if not re.match(r"Format:", text):
        return [name for phrase, name in FREE_FORM if phrase in text.upper()]
    names = []
    for para in re.split(r"\n\s*\n", text):
        if re.search(r"^Files:", para, re.M):
            m = re.search(r"^License:[ \t]*(.+)$", para, re.M)
            if m and m.group(1).strip() not in names:
                names.append(m.group(1).strip())
    return names


def archives_of_map(path):
    """The static archives (lib*.a) a GNU ld map pulled members from."""
    archives = []
    for m in re.finditer(r"^(/\S+?\.a)\(", Path(path).read_text(errors="replace"), re.M):
        if m.group(1) not in archives:
            archives.append(m.group(1))
    return archives


def package_of(path):
    name = Path(path).name
    pkg = owner(path)
    if pkg is None and name in MINGW_BUILT:
        return MINGW_BUILT[name], "built for Windows by scripts/mingw-deps.sh from the same Debian source"
    return pkg, ""


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--bundled")
    ap.add_argument("--link-map")
    ap.add_argument("--compiled-in", nargs="*", default=[])
    ap.add_argument("--windows-map")
    args = ap.parse_args(argv)

    # (what the package carries, how) -> package; one notice per package.
    entries = []  # (package, item, how, note)
    if args.bundled:
        for line in Path(args.bundled).read_text().splitlines():
            name, source = line.split(" ", 1)
            pkg, note = package_of(source)
            entries.append((pkg, name, "shared library bundled as lib/" + name, note, source))
    if args.link_map:
        for a in archives_of_map(args.link_map):
            pkg, note = package_of(a)
            entries.append((pkg, Path(a).name, "static archive linked into libfracterra", note, a))
    for h in args.compiled_in:
        pkg, note = package_of(h)
        entries.append((pkg, Path(h).name, "header-only library compiled into libfracterra", note, h))
    if args.windows_map and not Path(args.windows_map).is_file():
        # A Windows build from before the link map: say so (check_notices.py fails on it).
        entries.append(("?", "fracterra.dll", "its link map " + args.windows_map + " is missing: "
                        "build it again with scripts/build-windows.sh", "", args.windows_map))
    elif args.windows_map:
        for a in archives_of_map(args.windows_map):
            pkg, note = package_of(a)
            entries.append((pkg, Path(a).name, "static archive linked into fracterra.dll", note, a))
    unknown = [str(e[4]) for e in entries if e[0] is None]
    if unknown:
        sys.exit("third_party_notices: no Debian package owns " + ", ".join(unknown) +
                 " (its licence is unknown; add it to MINGW_BUILT if it is built from a Debian source)")
    entries = [e for e in entries if e[0] not in SYSTEM_PACKAGES]

    by_package = {}
    for pkg, item, how, note, _ in entries:
        by_package.setdefault(pkg, []).append((item, how, note))
    out = ["THIRD-PARTY NOTICES", "",
           "fracterra is licensed under the GNU General Public License, version 3 or later (LICENSE).",
           "This package carries the third-party software listed below, each under its own licence.",
           "Generated from the packaging step by scripts/third_party_notices.py; the licences and",
           "copyright texts are those of the Debian packages the files come from.", ""]
    index = ["Contents (file: package, licences):", ""]
    texts = []
    for pkg in sorted(by_package):
        if pkg == "?":
            index += [f"  {item}: UNKNOWN ({how})" for item, how, _ in by_package[pkg]]
            continue
        text = copyright_text(pkg)
        if text is None:
            sys.exit(f"third_party_notices: /usr/share/doc/{pkg}/copyright is missing")
        names = licences(text) or ["see its copyright text below"]
        for item, how, note in by_package[pkg]:
            index.append(f"  {item}: {pkg} {version(pkg)}; {', '.join(names)} ({how}{'; ' + note if note else ''})")
        texts += ["=" * 78, f"{pkg} {version(pkg)}", f"Licences: {', '.join(names)}", "=" * 78, "", text.rstrip(), ""]
    Path(args.out).write_text("\n".join(out + index + [""] + texts) + "\n", encoding="utf-8")
    print(f"third_party_notices: {len(entries)} files from {len(by_package)} packages -> {args.out}")


if __name__ == "__main__":
    main(sys.argv[1:])
