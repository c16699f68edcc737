# SPDX-License-Identifier: GPL-3.0-or-later
"""The CLI on a system without GDAL: FRACTERRA_GDAL names a library that does
not exist, the only candidate the library then tries (core/gdal_library.hpp).
GeoTIFF output and input fail with the message that says what to install;
PNG, OpenEXR and RAW16 are written and read back; the version names no GDAL.
And, as a control, the same GeoTIFF is written when GDAL is found.

Run as: python3 check_without_gdal.py FRACTERRA_CLI WORK_DIR
"""

import os
import subprocess
import sys
from pathlib import Path


def run(cli, args, gdal):
    env = dict(os.environ)
    if gdal:
        env.pop("FRACTERRA_GDAL", None)
    else:
        env["FRACTERRA_GDAL"] = "/nonexistent/libgdal.so"
    return subprocess.run([cli] + args, env=env, capture_output=True, text=True)


def main(cli, work):
    work = Path(work)
    work.mkdir(parents=True, exist_ok=True)
    problems = []

    def expect(ok, what):
        if not ok:
            problems.append(what)

    version = run(cli, ["--version"], gdal=False)
    expect(version.returncode == 0 and "gdal" not in version.stdout.split("optional libraries:")[-1],
           f"--version without GDAL: {version.stdout!r}")
    for ext in (".png", ".exr", ".raw"):
        out = work / ("t" + ext)
        r = run(cli, ["terrain", "--levels", "5", "--out", str(out)], gdal=False)
        expect(r.returncode == 0 and out.is_file(), f"terrain --out {out.name} without GDAL: {r.stderr}")
        back = run(cli, ["relief", "--in", str(out), "--out", str(work / f"relief{ext}.png")], gdal=False)
        expect(back.returncode == 0, f"relief --in {out.name} without GDAL: {back.stderr}")
    tif = work / "t.tif"
    tif.unlink(missing_ok=True)
    r = run(cli, ["terrain", "--levels", "5", "--out", str(tif)], gdal=False)
    expect(r.returncode != 0 and not tif.exists(), "terrain --out t.tif without GDAL succeeded")
    for needle in ("t.tif", "needs GDAL", "apt install gdal-bin", "/nonexistent/libgdal.so"):
        expect(needle in r.stderr, f"the refusal of t.tif lacks {needle!r}: {r.stderr!r}")
    # The control: with the system's GDAL the same file is written and read.
    r = run(cli, ["terrain", "--levels", "5", "--out", str(tif)], gdal=True)
    expect(r.returncode == 0 and tif.is_file(), f"terrain --out t.tif with GDAL: {r.stderr}")
    r = run(cli, ["relief", "--in", str(tif), "--out", str(work / "relief_tif.png")], gdal=False)
    expect(r.returncode != 0 and "apt install gdal-bin" in r.stderr, f"relief --in t.tif without GDAL: {r.stderr!r}")
    for p in problems:
        print("FAIL:", p)
    print("ok" if not problems else f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
