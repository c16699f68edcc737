# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on zip is self-contained: every shared library in its lib/ needs
only glibc, the C++ runtime (which the bundled OpenSubdiv needs and Blender
itself loads) and the other libraries beside it; libfracterra.so finds them
through RPATH $ORIGIN, links its own C++ runtime in, and exports only ft_*.
When the zip carries lib/fracterra.dll (the Windows build), the DLL needs only
Windows' own DLLs and exports only ft_* (tests/windows/check_dll.py), and the
4.2+ manifest lists both platforms; without it, Linux only.

Run as: python3 check_zip.py fracterra.zip      (uses binutils' readelf and nm;
x86_64-w64-mingw32-objdump for the DLL)
"""

import re
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "windows"))
import check_dll  # noqa: E402  (tests/windows: the DLL's imports and exports)

SYSTEM = {"libc.so.6", "libm.so.6", "ld-linux-x86-64.so.2", "libpthread.so.0", "libdl.so.2", "librt.so.1"}
CXX_RUNTIME = {"libstdc++.so.6", "libgcc_s.so.1"}


def dynamic(path):
    out = subprocess.run(["readelf", "-d", str(path)], check=True, capture_output=True, text=True).stdout
    needed = re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", out)
    rpath = re.findall(r"\((RPATH|RUNPATH)\)\s+Library (?:rpath|runpath): \[(.+?)\]", out)
    return needed, rpath


def main(zip_path):
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        zipfile.ZipFile(zip_path).extractall(tmp)
        lib = Path(tmp, "fracterra", "lib")
        bundled = {p.name for p in lib.iterdir()}
        dll = lib / "fracterra.dll"
        platforms = re.search(r"^platforms = (.*)$", Path(tmp, "fracterra", "blender_manifest.toml").read_text(),
                              re.M).group(1)
        want = '["linux-x64", "windows-x64"]' if dll.is_file() else '["linux-x64"]'
        if platforms != want:
            problems.append(f"blender_manifest.toml lists platforms = {platforms}, expected {want}")
        if dll.is_file():
            problems += check_dll.problems_of(dll)
        print(f"platforms = {platforms}")
        for path in sorted(p for p in lib.iterdir() if p.suffix != ".dll"):
            needed, _ = dynamic(path)
            allowed = SYSTEM | bundled | (CXX_RUNTIME if path.name != "libfracterra.so" else set())
            for name in needed:
                if name not in allowed:
                    problems.append(f"{path.name} needs {name}, which is neither bundled nor allowed")
            print(f"{path.name}: needs {', '.join(needed)}")
        _, rpath = dynamic(lib / "libfracterra.so")
        if rpath != [("RPATH", "$ORIGIN")]:
            problems.append(f"libfracterra.so: expected RPATH $ORIGIN (DT_RPATH, so it also serves the bundled "
                            f"libraries' own dependencies), got {rpath}")
        symbols = subprocess.run(["nm", "-D", "--defined-only", str(lib / "libfracterra.so")], check=True,
                                 capture_output=True, text=True).stdout.split("\n")
        exported = [line.split()[-1] for line in symbols if line.strip()]
        stray = [s for s in exported if not s.startswith("ft_")]
        if stray:
            problems.append(f"libfracterra.so exports {len(stray)} symbols outside ft_*: {stray[:10]}")
        if not any(s == "ft_abi_version" for s in exported):
            problems.append("libfracterra.so does not export ft_abi_version")
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
