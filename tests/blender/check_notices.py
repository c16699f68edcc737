# SPDX-License-Identifier: GPL-3.0-or-later
"""Every package's THIRD_PARTY_NOTICES lists exactly the shared libraries it
bundles, each with a Debian package and a licence, and what fracterra.dll
links in when the package carries the DLL; and each package stays within its
size budget (the add-on zip and the Linux extension: 15 MB, the issue's bound
once GDAL's tree left them; the zip with fracterra.dll beside: 20 MB).

A package is an add-on zip (fracterra/lib/, fracterra/THIRD_PARTY_NOTICES), an
extension zip (the same, its lib/ in wheels/fracterra_native-*.whl) or a wheel
(fracterra/lib/ or fracterra_native/lib/ and the THIRD_PARTY_NOTICES beside).

Run as: python3 check_notices.py PACKAGE...
"""

import io
import os
import re
import sys
import zipfile
from pathlib import PurePosixPath

MB = 1024 * 1024
BUDGET = {"linux": 15 * MB, "with_dll": 20 * MB}
# Our own files, which the notices do not list.
OURS = {"libfracterra.so", "fracterra.dll"}


def listed(notices):
    """{file name: (package, licences, how)} of the notices' contents lines."""
    out = {}
    for m in re.finditer(r"^  (\S+): (\S+) \S+; (.*) \((.*)\)$", notices, re.M):
        out.setdefault(m.group(1), []).append((m.group(2), m.group(3), m.group(4)))
    return out


def libraries_and_notices(archive, label):
    """[(lib/ folder, [file names], notices text)] of a package and of the wheels inside it."""
    found = []
    names = archive.namelist()
    for notices_name in [n for n in names if n.endswith("THIRD_PARTY_NOTICES")]:
        folder = str(PurePosixPath(notices_name).parent)
        libs = [PurePosixPath(n).name for n in names if str(PurePosixPath(n).parent) == folder + "/lib"]
        found.append((f"{label}:{folder}", libs, archive.read(notices_name).decode("utf-8")))
    for wheel in [n for n in names if n.endswith(".whl")]:
        found += libraries_and_notices(zipfile.ZipFile(io.BytesIO(archive.read(wheel))), f"{label}:{wheel}")
    return found


def problems_of(path):
    problems = []
    archive = zipfile.ZipFile(path)
    parts = libraries_and_notices(archive, PurePosixPath(path).name)
    has_libraries = any(libs for _, libs, _ in parts)
    if not has_libraries:
        problems.append(f"{path}: no lib/ folder with a THIRD_PARTY_NOTICES beside it")
    for where, libs, notices in parts:
        if not libs:
            continue
        entries = listed(notices)
        bundled = {n for n in libs if n not in OURS}
        noted = {n for n, e in entries.items() if any("bundled as lib/" in how for _, _, how in e)}
        for n in sorted(bundled - noted):
            problems.append(f"{where}: lib/{n} is bundled and has no notice")
        for n in sorted(noted - bundled):
            problems.append(f"{where}: the notices list lib/{n}, which is not bundled")
        for n, e in entries.items():
            for pkg, licences, how in e:
                if not licences.strip():
                    problems.append(f"{where}: {n} ({pkg}) has no licence")
        if "UNKNOWN" in notices:
            problems.append(f"{where}: the notices hold an UNKNOWN entry: "
                            + re.search(r"^.*UNKNOWN.*$", notices, re.M).group(0).strip())
        if "libfracterra.so" in libs and not any("linked into libfracterra" in h for e in entries.values()
                                                 for _, _, h in e):
            problems.append(f"{where}: the notices name nothing linked into libfracterra.so (its link map?)")
        if "fracterra.dll" in libs and not any("linked into fracterra.dll" in h for e in entries.values()
                                               for _, _, h in e):
            problems.append(f"{where}: lib/fracterra.dll is carried and the notices name nothing linked into it")
        print(f"{where}: {len(bundled)} bundled libraries, {sum(map(len, entries.values()))} notice entries")
    size = os.path.getsize(path)
    with_dll = any("fracterra.dll" in libs for _, libs, _ in parts)
    linux_only = "windows_x64" not in path and not with_dll
    budget = BUDGET["linux"] if linux_only else BUDGET["with_dll"]
    if path.endswith(".zip") and size > budget:
        problems.append(f"{path}: {size / MB:.1f} MB, over its budget of {budget / MB:.0f} MB")
    print(f"{path}: {size / MB:.1f} MB (budget {budget / MB:.0f} MB)")
    return problems


def main(paths):
    problems = [p for path in paths for p in problems_of(path)]
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
