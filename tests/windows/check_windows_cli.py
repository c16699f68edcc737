# SPDX-License-Identifier: GPL-3.0-or-later
"""fracterra.exe (the Windows build, run under Wine) against the Linux build.

  same_bits     a terrain of each kind of method (midpoint, fBm, spectral: FFTW),
                an erosion with its maps, a polyline, an analysis and a POV-Ray
                scene, made by both programs from the same arguments: every file
                and the JSON they print must be the same to the byte. The
                counter-based RNG promises the same numbers on every machine;
                this checks that the Windows compiler, C runtime and FFTW keep it.
  unicode_path  a terrain written to "Z:\\...\\Dossier été\\terrain.png" (a Windows
                path with a space and non-ASCII letters), read back by `relief`
                and `analyze`: the files land under that name, UTF-8 on Linux's side;
                in that folder, `planet` makes "planète" and writes its cube
                faces there, `tiles --engine unity` makes the tile set "carrés"
                and cuts it (reading its tiles back) into carrés\\unity:
                every file the Linux build's bytes.
  refusals      what the Windows build goes without (GDAL, OpenEXR, OpenSubdiv)
                is refused with the library's name and the formats it has;
                `render` spawns its program through CreateProcessW and reports
                the program's exit code and error text.

Run as: python3 check_windows_cli.py CASE WINDOWS_EXE LINUX_CLI
Exit 77 (skip) when Wine or a build is missing, with the reason.
Checked by breaking it: with utf8_arguments() returning argv as Windows hands
it over (the ANSI code page), unicode_path failed ("folder ... does not
exist"); so it did with `planet`'s folder made by create_directories(o.out)
(it made "Dossier Ã©tÃ©\\planÃ¨te") and with the engine tiles' folder so made
("folder ...\\carrés\\unity does not exist"); see docs/windows.md for the bit
comparisons' history.
"""

import filecmp
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
WINE_RUN = HERE / "wine_run.sh"
SKIP = 77


class Skip(Exception):
    pass


def run_windows(exe, args, cwd):
    """fracterra.exe ARGS under Wine in `cwd`: (exit code, stdout, stderr)."""
    r = subprocess.run([str(WINE_RUN), str(exe), *args], cwd=cwd, capture_output=True, timeout=300)
    out = r.stdout.decode("utf-8", "replace").replace("\r\n", "\n")
    if r.returncode == SKIP and out.startswith("SKIP:"):
        raise Skip(out.strip())
    return r.returncode, out, r.stderr.decode("utf-8", "replace").replace("\r\n", "\n")


def run_linux(cli, args, cwd):
    r = subprocess.run([str(cli), *args], cwd=cwd, capture_output=True, timeout=300)
    return r.returncode, r.stdout.decode(), r.stderr.decode()


def windows_path(path):
    """The path Wine's Windows programs see for a Linux path: drive Z: is the root."""
    return "Z:" + str(path).replace("/", "\\")


# The commands both builds run; files are compared byte for byte, and so is
# what each prints (the analysis JSON). Small sizes: Wine starts in ~0.5 s and
# the whole case takes seconds.
SAME_BITS = [
    ["terrain", "--method", "midpoint", "--levels", "8", "--hurst", "0.8", "--seed", "7", "--out", "t.npy"],
    ["terrain", "--method", "midpoint", "--levels", "8", "--hurst", "0.8", "--seed", "7", "--out", "t.png"],
    ["terrain", "--method", "fbm", "--size", "160x120", "--seed", "5", "--out", "fbm.npy"],
    ["terrain", "--method", "spectral", "--size", "128x96", "--hurst", "0.7", "--seed", "3", "--out", "spectral.npy"],
    ["erode", "--in", "t.npy", "--preset", "land", "--out", "e.npy", "--maps", "maps"],
    ["polyline", "--method", "fpl", "--base", "0,0;1,0", "--depth", "9", "--seed", "11", "--out", "line.csv"],
    ["analyze", "t.npy"],
    ["scene", "--terrain", "t.png", "--polyline", "line.csv", "--pov", "scene.pov"],
]


def same_bits(exe, cli):
    with tempfile.TemporaryDirectory() as tmp:
        lin, win = Path(tmp, "linux"), Path(tmp, "windows")
        lin.mkdir()
        win.mkdir()
        problems = []
        for args in SAME_BITS:
            rl, out_l, err_l = run_linux(cli, args, lin)
            rw, out_w, err_w = run_windows(exe, args, win)
            name = " ".join(args[:3])
            if rl != 0 or rw != 0:
                problems.append(f"{name}: exit codes Linux {rl}, Windows {rw}: {err_l.strip()} | {err_w.strip()}")
            elif out_l != out_w:
                problems.append(f"{name}: printed differently:\n  Linux:   {out_l[:300]}\n  Windows: {out_w[:300]}")
        files = sorted(p.relative_to(lin) for p in lin.rglob("*") if p.is_file())
        for rel in files:
            other = win / rel
            if not other.is_file():
                problems.append(f"{rel}: written on Linux only")
            elif not filecmp.cmp(lin / rel, other, shallow=False):
                problems.append(f"{rel}: differs ({(lin / rel).stat().st_size} bytes on Linux, "
                                f"{other.stat().st_size} on Windows)")
        extra = sorted(str(p.relative_to(win)) for p in win.rglob("*") if p.is_file() and not (lin / p.relative_to(win)).is_file())
        if extra:
            problems.append(f"written on Windows only: {extra}")
        print(f"compared {len(files)} files of {len(SAME_BITS)} commands")
        return problems


def unicode_path(exe, cli):
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp, "Dossier été")
        folder.mkdir()
        terrain = windows_path(folder / "terrain.png")
        args = ["terrain", "--method", "midpoint", "--levels", "7", "--seed", "9", "--out"]
        problems = []
        r, _, err = run_windows(exe, [*args, terrain], tmp)
        if r != 0:
            return [f"writing {terrain}: exit {r}: {err.strip()}"]
        r, _, err = run_windows(exe, ["relief", "--in", terrain, "--out", windows_path(folder / "relief.png")], tmp)
        if r != 0:
            problems.append(f"relief of {terrain}: exit {r}: {err.strip()}")
        r, out, err = run_windows(exe, ["analyze", terrain], tmp)
        if r != 0:
            problems.append(f"analyze {terrain}: exit {r}: {err.strip()}")
        else:
            try:
                json.loads(out)
            except ValueError:
                problems.append(f"analyze {terrain} printed no JSON: {out[:200]}")
        # The names on disk are the UTF-8 ones (not the ANSI code page's bytes), nothing else is left
        # (no temporary file), and the terrain is the Linux build's to the byte.
        names = sorted(os.listdir(folder))
        if names != ["relief.png", "terrain.png"]:
            problems.append(f"the folder holds {names}, expected relief.png and terrain.png")
        lin = Path(tmp, "linux")
        lin.mkdir()
        run_linux(cli, [*args, "terrain.png"], lin)
        if (folder / "terrain.png").is_file() and not filecmp.cmp(lin / "terrain.png", folder / "terrain.png", shallow=False):
            problems.append("terrain.png written under the non-ASCII path differs from the Linux build's")
        problems += unicode_planet_and_tiles(exe, cli, folder, tmp)
        print(f"wrote and read back {terrain}, a planet's cube folder and a tile set cut for Unity in it")
        return problems


def same_files(lin, win, names):
    """The files `names` of folders `lin` and `win` that are missing or differ."""
    return [n for n in names if not (win / n).is_file() or not filecmp.cmp(lin / n, win / n, shallow=False)]


def unicode_planet_and_tiles(exe, cli, folder, tmp):
    """`planet` making a non-ASCII folder in `folder` and writing its faces and
    planet.json there; `tiles --engine unity` making a non-ASCII tile set
    there, reading its tiles back and cutting them into OUT/unity/. Each file
    has its UTF-8 name and the Linux build's bytes; the JSON printed and
    written names the folders as given. (Two Wine starts: ~6 s at load 7.)"""
    problems = []
    lin = Path(tmp, "linux")
    planet = ["planet", "--layout", "cube", "--level", "4", "--seed", "9", "--format", ".png", "--out"]
    r, _, err = run_windows(exe, [*planet, windows_path(folder / "planète")], tmp)
    if r != 0:
        return [f"planet into {folder / 'planète'}: exit {r}: {err.strip()}"]
    run_linux(cli, [*planet, "planète"], lin)
    faces = [f"face_{n}.png" for n in ("px", "nx", "py", "ny", "pz", "nz")]
    names = sorted(os.listdir(folder / "planète")) if (folder / "planète").is_dir() else []
    if names != sorted([*faces, "planet.json"]):
        problems.append(f"planète holds {names} (of {sorted(os.listdir(folder))}), expected the 6 faces and planet.json")
    elif bad := same_files(lin / "planète", folder / "planète", [*faces, "planet.json"]):
        problems.append(f"planète: {bad} differ from the Linux build's")

    tiles = ["tiles", "--method", "midpoint", "--levels", "7", "--seed", "9", "--tile", "64", "--quiet",
             "--engine", "unity", "--out"]
    win_set = windows_path(folder / "carrés")
    r, out, err = run_windows(exe, [*tiles, win_set], tmp)
    if r != 0:
        return problems + [f"tiles --engine unity into {win_set}: exit {r}: {err.strip()}"]
    run_linux(cli, [*tiles, "carrés"], lin)
    printed = json.loads(out)
    engine = printed.get("engine", {})
    if printed["written"] != 4 or (engine.get("folder"), engine.get("sidecar")) != (
            win_set + "\\unity", win_set + "\\unity\\unity.json"):
        problems.append(f"tiles --engine unity wrote {printed['written']} of 4 tiles and printed {engine}, "
                        f"not the folders under {win_set}")
    tile_files = [f"tile_r00{y}_c00{x}.{e}" for y in (0, 1) for x in (0, 1) for e in ("png", "pgw")]
    unity_files = [f"unity/terrain_{x}_{y}.raw" for y in (0, 1) for x in (0, 1)]
    if bad := same_files(lin / "carrés", folder / "carrés", [*tile_files, *unity_files]):
        problems.append(f"carrés: {bad} missing or not the Linux build's")
    sidecar = folder / "carrés" / "unity" / "unity.json"
    if not sidecar.is_file() or json.loads(sidecar.read_text(encoding="utf-8")).get("tile_set") != "carrés":
        problems.append(f"{sidecar} is missing or does not name its tile set carrés")
    return problems


def refusals(exe, cli):
    problems = []
    formats = "PNG, PGM, NPY and RAW16"
    with tempfile.TemporaryDirectory() as tmp:
        t = ["terrain", "--levels", "5", "--out"]
        expect = [
            ([*t, "t.tif"], ["GeoTIFF", "needs GDAL", formats]),
            ([*t, "t.exr"], ["OpenEXR", "needs OpenEXR", formats]),
            ([*t, "t.hgt"], ["unsupported heightfield format (use .png, .pgm, .npy, .raw or .r16)"]),
            (["relief", "--in", "dem.hgt", "--out", "r.png"], ["'.hgt'", "needs GDAL", formats]),
        ]
        Path(tmp, "dem.hgt").write_bytes(bytes(2 * 1201 * 1201))  # an SRTM tile's size, all zeros
        Path(tmp, "cube.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")
        expect.append((["fractalize", "--in", "cube.obj", "--levels", "2", "--out", "rock.obj"], ["needs OpenSubdiv"]))
        for args, words in expect:
            r, _, err = run_windows(exe, args, tmp)
            missing = [w for w in words if w not in err]
            if r == 0 or missing:
                problems.append(f"{' '.join(args)}: exit {r}, message lacks {missing}: {err.strip()}")
        r, out, _ = run_windows(exe, ["--version"], tmp)
        if f"heightfield formats: {formats}" not in out or "optional libraries: none" not in out:
            problems.append(f"--version does not say what the build has: {out.strip()}")
        # render spawns FT_POVRAY with POV-Ray's options. fracterra.exe itself stands in: it refuses
        # them ("A subcommand is required", exit 106), so the message must carry its exit code and its
        # own error text, read from its stderr through the pipe.
        run_windows(exe, ["terrain", "--levels", "4", "--out", "t.png"], tmp)
        run_windows(exe, ["scene", "--terrain", "t.png", "--pov", "s.pov"], tmp)
        # Wine passes the Linux environment to Windows programs.
        os.environ["FT_POVRAY"] = windows_path(exe)
        r, _, err = run_windows(exe, ["render", "s.pov", "--width", "8", "--height", "8", "--out", "s.png"], tmp)
        if r == 0 or "povray failed" not in err or "exit code 106" not in err or "subcommand is required" not in err:
            problems.append(f"render through CreateProcessW: exit {r}: {err.strip()[:400]}")
        os.environ["FT_POVRAY"] = "no-such-povray"
        r, _, err = run_windows(exe, ["render", "s.pov", "--out", "s.png"], tmp)
        if r == 0 or "cannot run 'no-such-povray'" not in err:
            problems.append(f"render with a missing program: exit {r}: {err.strip()[:300]}")
        del os.environ["FT_POVRAY"]
        if Path(tmp, "s.png").exists():
            problems.append("a failed render left s.png behind")
        print(f"checked {len(expect)} refusals, --version and two renders")
    return problems


def main(case, exe, cli):
    exe, cli = Path(exe).resolve(), Path(cli).resolve()
    try:
        if case != "refusals" and not cli.is_file():
            raise Skip(f"SKIP: the Linux build's {cli} is missing (scripts/build.sh)")
        problems = {"same_bits": same_bits, "unicode_path": unicode_path, "refusals": refusals}[case](exe, cli)
    except Skip as e:
        print(e)
        return SKIP
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
