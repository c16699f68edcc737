#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Windows extension's native wheel as Blender on Windows would use it,
as far as this machine allows (docs/windows.md):

- the windows-x64 extension zip holds exactly one wheel, tagged
  py3-none-win_amd64 in its name and in its WHEEL file, holding
  fracterra_native/lib/fracterra.dll;
- the wheel is unpacked as an installer unpacks it into site-packages, and the
  add-on binding's own lookup (find_spec("fracterra_native"), then
  lib/<the Windows library name>) finds the DLL there;
- under Wine, dll_probe.exe loads that DLL as CPython's ctypes.CDLL does on
  Windows (LoadLibraryExW of the full path, searching only its folder and the
  system's), resolves every symbol of the binding's table, and reports an ABI
  version that the binding accepts.

No Windows CPython can be had here (no registry this machine reaches carries
one; the npm packages that install one download it from elsewhere), so a
small C program stands in for ctypes.

Usage: check_wheel_dll.py EXTENSIONS_DIR DLL_PROBE_C ADDON_DIR WINE_RUN_SH
(dll_probe.c is compiled with mingw-w64's gcc). Exit 77 (skipped) when the
windows-x64 zip, mingw-w64 or Wine is missing.
"""

import glob
import importlib.util
import io
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def main():
    ext_dir, probe_source, addon_dir, wine_run = (Path(a) for a in sys.argv[1:5])
    zips = sorted(glob.glob(str(ext_dir / "fracterra-*-windows_x64.zip")))
    if not zips:
        print(f"SKIP: no windows-x64 extension in {ext_dir} (scripts/build-windows.sh, then "
              "cmake --build build --target fracterra_extensions)")
        sys.exit(77)
    ext_zip = Path(zips[-1])
    gcc = shutil.which("x86_64-w64-mingw32-gcc-posix") or shutil.which("x86_64-w64-mingw32-gcc")
    if gcc is None:
        print("SKIP: mingw-w64's gcc is missing (scripts/install-deps.sh windows)")
        sys.exit(77)
    sys.path.insert(0, str(addon_dir))
    from fracterra.core import binding  # pylint: disable=import-outside-toplevel (bpy-free)

    with zipfile.ZipFile(ext_zip) as z:
        wheels = [n for n in z.namelist() if n.endswith(".whl")]
        if len(wheels) != 1 or not wheels[0].endswith("-py3-none-win_amd64.whl"):
            fail(f"{ext_zip.name} should hold one py3-none-win_amd64 wheel, holds {wheels}")
        wheel_bytes = z.read(wheels[0])
    with zipfile.ZipFile(io.BytesIO(wheel_bytes)) as w:
        names = w.namelist()
        wheel_files = [n for n in names if n.endswith(".dist-info/WHEEL")]
        if len(wheel_files) != 1:
            fail(f"{wheels[0]} has {len(wheel_files)} WHEEL files")
        tags = [line.split(":", 1)[1].strip() for line in w.read(wheel_files[0]).decode().splitlines()
                if line.startswith("Tag:")]
        if tags != ["py3-none-win_amd64"]:
            fail(f"{wheels[0]}'s WHEEL says Tag {tags}, not py3-none-win_amd64")
        if binding.WHEEL_PACKAGE + "/lib/fracterra.dll" not in names:
            fail(f"{wheels[0]} lacks {binding.WHEEL_PACKAGE}/lib/fracterra.dll: {names}")
        so = [n for n in names if n.endswith(".so")]
        if so:
            fail(f"the Windows wheel carries Linux libraries: {so}")
        with tempfile.TemporaryDirectory() as tmp:
            probe = Path(tmp) / "dll_probe.exe"
            subprocess.run([gcc, "-O2", "-Wall", "-o", str(probe), str(probe_source), "-lshell32"], check=True)
            site = Path(tmp) / "site-packages"
            w.extractall(site)  # what pip and Blender's wheel installer do with a purelib wheel
            sys.path.insert(0, str(site))
            spec = importlib.util.find_spec(binding.WHEEL_PACKAGE)
            # binding.wheel_library_path() with the Windows library's name.
            dll = Path(spec.origin).resolve().parent / "lib" / binding.LIBRARY_NAMES[("win32", "amd64")]
            if not dll.is_file():
                fail(f"the binding would look for {dll}, which the wheel does not make")
            symbols = "".join(f"{name}\n" for name in binding.SIGNATURES)
            windows_path = "Z:" + str(dll).replace("/", "\\")
            run = subprocess.run([str(wine_run), str(probe), windows_path], input=symbols, capture_output=True,
                                 text=True, timeout=300, check=False)
            out = run.stdout
            print(out.strip())
            if run.returncode == 77:
                sys.exit(77)
            if run.returncode != 0:
                fail(f"dll_probe.exe exited {run.returncode}: {run.stderr.strip()}")
            abi = [line.split()[1] for line in out.splitlines() if line.startswith("abi ")]
            major, minor = (int(x) for x in abi[0].split("."))
            if major != binding.ABI_MAJOR or minor < binding.ABI_MINOR_MIN:
                fail(f"the DLL has ABI {major}.{minor}; the binding needs {binding.ABI_MAJOR}.{binding.ABI_MINOR_MIN}+")
    print(f"OK: {wheels[0]}: fracterra.dll loads from where the binding looks, ABI {major}.{minor}, "
          f"all {len(binding.SIGNATURES)} symbols of the binding resolve")


if __name__ == "__main__":
    main()
