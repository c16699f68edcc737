#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that the native code's includes point only downwards.

native/src/ is layered by capability, one folder per layer; native/cli/ is the
`fracterra` tool. A file may include a project header of its own layer or of
a layer of lower rank, never one of the same rank (sideways) or higher
(upwards). The ranks are LAYERS below, each with what it holds; `--picture`
prints them as docs/architecture.md shows them, and the check fails when the
two differ (`--write-picture` rewrites the document's picture).

Public headers (`fracterra/*.h`, the C ABI) are included by capi/ and cli/, and
by the layer a header is named after (terrain/ includes fracterra/terrain.h for
its params struct); `fracterra/fracterra.h` (all of them) only by capi/ and
cli/; a header named after no layer (core.h: status codes) by anyone.
Third-party headers with one home: OpenSubdiv only in subdiv/, CLI11 only in
cli/.

A folder that is not in the table is an error too: a new layer gets its row
in LAYERS (and `--write-picture` puts it into docs/architecture.md).

Namespaces follow the folders, one layer = one namespace, as OpenSubdiv's
Sdc/Vtr/Far do: core/ is the root namespace `ft` (everything stands on it);
every other folder X/ is `ft::X` (io/ -> ft::io, noise/ -> ft::noise, ...;
cli/ -> ft::cli, capi/ -> ft::capi), except povray/, which is `ft::pov` (it
was so before the rule, and `pov` names the language its files write).
Private helpers go in `ft::X::detail` or an anonymous namespace; callers in
other layers qualify (`io::read_heightfield`) or put a using-declaration at the
top of a .cpp, never `using namespace` in a header. A layer's namespace may
share its name with a type (`ft::mesh` beside `ft::Mesh`) or with a function
inside another namespace, never with a function or variable of its own
enclosing scope `ft`. Every .hpp/.cpp of native/src/X/ and native/cli/ must
open its layer's namespace (or one nested in it) and no other `ft` namespace;
a file may open none only if it is capi/'s `extern "C"` code or holds only
preprocessor lines. NAMESPACE_TODO lists what is still in plain `ft` (nothing now).

Usage:

    scripts/check_layers.py [--root DIR]     # exit 1 and one line per violation
    scripts/check_layers.py --self-test      # the check catches planted bad includes
    scripts/check_layers.py --picture        # the layer picture, generated from LAYERS
    scripts/check_layers.py --write-picture  # ... written into docs/architecture.md
"""

import argparse
import re
import sys
import tempfile
from pathlib import Path

# Every layer: its rank and what it holds (the picture in docs/architecture.md
# is generated from these rows).
LAYERS = {
    "core": (0, "rng, errors, heightfield, polyline set, gray image, memory cap, threads; platform*: the OS calls"),
    "io": (1, "files: PNG, PGM, npy, RAW16, OpenEXR, GDAL rasters and vectors, OBJ, PLY, SVG plots"),
    "noise": (1, "noise bases and the fBm octave sum, in 2D and 3D"),
    "contour": (1, "level sets by marching squares (coastlines, shorelines, curves of equal escape time)"),
    "mesh": (1, "grid topology for Blender's mesh arrays"),
    "preview": (1, "shaded relief"),
    "analysis": (1, "H, D, spectra, the polyline statistics, Horton's ratios"),
    "terrain": (2, "the method table terrain_methods.hpp, one *_method.cpp per method; landforms; windows"),
    "splat": (2, "splat and colour maps by layer rules, their table and JSON (PNGs through io/)"),
    "polyline": (3, "fractal polylines (the profile method uses terrain/'s 1D Voss profile; the FPL study, analysis/)"),
    "refine": (3, "a real DEM refined by terrain/'s midpoint method, H from analysis/"),
    "tiles": (7, "tile sets larger than memory: windows of pipeline/'s terrains, generated or eroded, and their maps; manifests, VRT mosaics through io/"),
    "planet": (3, "fractal planets: fBm on the sphere (noise/), midpoint displacement on the cube-sphere; layouts"),
    "subdiv": (4, "fractalize meshes: the only OpenSubdiv user"),
    "povray": (4, "POV-Ray scenes: height_field, sphere_sweep, mesh2, lights and sky (files through io/)"),
    "erosion": (4, "the landscape model; fluvial, hydraulic, thermal passes; flow routing; maps; drainage statistics"),
    "engines": (8, "Unity, Unreal, Godot: sizes, formats, sidecars, tile sets cut for them (io/, splat/, tiles/)"),
    "hydrology": (5, "rivers, lakes, the sea (erosion/'s flow graph, polyline/'s FPL, contour/'s shorelines)"),
    "pipeline": (6, "generate -> landform -> erode -> maps -> rivers in one call (ft_terrain_build)"),
    "tables": (7, "every layer's parameter table by kind (ft_params_describe, `fracterra params`)"),
    "capi": (9, "the extern \"C\" ABI: libfracterra.so = capi/ + the static core"),
    "cli": (9, "the fracterra tool: links the static core and calls the C++ layers; neither includes capi/"),
}
RANK = {layer: rank for layer, (rank, _) in LAYERS.items()}
PICTURE_DOC = Path("docs/architecture.md")
PICTURE_BEGIN = "<!-- layers: generated by scripts/check_layers.py --write-picture -->"
PICTURE_END = "<!-- /layers -->"
TOP = {"capi", "cli"}  # may include any public header
# The namespace of each layer, where it is not ft::<folder>.
NAMESPACE = {"core": "ft", "povray": "ft::pov"}
# Still in plain `ft`, to be moved into their layer's namespace: whole layers
# or single files. Empty since issue 25 moved terrain/ and polyline/; a layer
# brought in from older code goes here until scripts/move_to_layer_namespace.py moves it.
NAMESPACE_TODO = set()
# Layers whose files may open no namespace at all (the extern "C" boundary).
NO_NAMESPACE_OK = {"capi"}
# Third-party include prefixes and the only layers that may include them.
THIRD_PARTY_HOME = {"opensubdiv/": {"subdiv"}, "CLI/": {"cli"}}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
OPENS = re.compile(r"^\s*namespace\s+(ft(?:::\w+)*)\s*\{", re.M)
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
SUFFIXES = {".h", ".hpp", ".cpp", ".inc", ".ipp"}


def layer_of(path, root):
    """The layer of a source file: cli for native/cli, else its folder in native/src."""
    rel = path.relative_to(root / "native")
    return "cli" if rel.parts[0] == "cli" else rel.parts[1]


def namespace_of(layer):
    return NAMESPACE.get(layer, f"ft::{layer}")


def namespace_violations(path, layer, where, text):
    """One message if the file opens another layer's namespace, or none where it must open one."""
    rel = "/".join(where.parts[-2:])
    if layer in NAMESPACE_TODO or rel in NAMESPACE_TODO:
        return []
    own = namespace_of(layer)
    opened = OPENS.findall(text)
    wrong = sorted({n for n in opened if n != own and not n.startswith(own + "::")})
    if wrong:
        return [f"{where}: opens namespace {', '.join(wrong)}; files of {layer}/ are in {own} "
                f"(or {own}::detail)"]
    # A .inc is a fragment its includer expands inside its own namespace (noise's
    # vector rows, once per instruction set), so it opens none itself.
    if not opened and layer not in NO_NAMESPACE_OK and where.suffix != ".inc":
        code = [l for l in COMMENT.sub("", text).splitlines() if l.strip() and not l.lstrip().startswith("#")]
        if code:
            return [f"{where}: declares code outside namespace {own}; open `namespace {own} {{`"]
    return []


def violations(root):
    """One message per include that points upwards or sideways (or into an unknown layer), and
    per file outside its layer's namespace."""
    out = []
    files = sorted(p for d in (root / "native" / "src", root / "native" / "cli") if d.is_dir()
                   for p in d.rglob("*") if p.suffix in SUFFIXES and p.is_file())
    for folder in sorted({layer_of(p, root) for p in files} - set(RANK)):
        out.append(f"native/src/{folder}/: a layer without a rank; give it a row in LAYERS in scripts/check_layers.py "
                   "(then --write-picture)")
    for path in files:
        layer = layer_of(path, root)
        if layer not in RANK:
            continue
        where = path.relative_to(root)
        text = path.read_text(errors="replace")
        out.extend(namespace_violations(path, layer, where, text))
        for number, line in enumerate(text.splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            kind, target = m.groups()
            at = f"{where}:{number}: {layer}/ includes {target}"
            if kind == "<":
                for prefix, homes in THIRD_PARTY_HOME.items():
                    if target.startswith(prefix) and layer not in homes:
                        out.append(f"{at}: only {', '.join(sorted(homes))}/ may include {prefix}")
                continue
            head, _, rest = target.partition("/")
            if not rest:
                continue  # a file beside this one (generated or local), not a layer
            if head == "fracterra":
                owner = Path(rest).stem
                if layer in TOP:
                    continue
                if owner == "fracterra":
                    out.append(f"{at}: the umbrella header is for capi/ and cli/ only")
                elif owner in RANK and owner != layer:
                    out.append(f"{at}: the public {rest} belongs to {owner}/ (and capi/, cli/); "
                               f"give {layer}/ its own C++ types")
                continue
            if head not in RANK:
                out.append(f"{at}: {head}/ is not a layer")
            elif head != layer and RANK[head] >= RANK[layer]:
                way = "sideways" if RANK[head] == RANK[layer] else "upwards"
                out.append(f"{at}: {way} ({head}/ has rank {RANK[head]}, {layer}/ rank {RANK[layer]})")
    return out


def picture():
    """The layer picture: one line per layer, highest rank first, as docs/architecture.md shows it."""
    lines = ["    rank  layer       what it holds"]
    for layer, (rank, what) in sorted(LAYERS.items(), key=lambda kv: (-kv[1][0], kv[0])):
        lines.append(f"    {rank:4d}  {layer + '/':<10}  {what}")
    return "\n".join(lines) + "\n"


def picture_in(doc):
    """The picture between the markers of `doc`, or None."""
    text = doc.read_text()
    if PICTURE_BEGIN not in text or PICTURE_END not in text:
        return None
    return text.split(PICTURE_BEGIN, 1)[1].split(PICTURE_END, 1)[0].strip("\n") + "\n"


def write_picture(doc):
    text = doc.read_text()
    head, rest = text.split(PICTURE_BEGIN, 1)
    tail = rest.split(PICTURE_END, 1)[1]
    doc.write_text(head + PICTURE_BEGIN + "\n\n" + picture() + "\n" + PICTURE_END + tail)


def picture_violations(root):
    doc = root / PICTURE_DOC
    if not doc.is_file():
        return []  # a scratch tree (the self-test)
    shown = picture_in(doc)
    if shown is None:
        return [f"{PICTURE_DOC}: no layer picture between {PICTURE_BEGIN} and {PICTURE_END}"]
    if shown.strip() != picture().strip():
        return [f"{PICTURE_DOC}: the layer picture differs from LAYERS in scripts/check_layers.py; "
                "run scripts/check_layers.py --write-picture"]
    return []


def self_test():
    """Plants one bad include of each kind in a scratch tree and checks each is reported,
    and that the same tree without them passes."""
    good = {
        "native/src/core/a.hpp": '#include "core/b.hpp"\n#include "fracterra/core.h"\nnamespace ft {\n}\n',
        "native/src/core/m.hpp": "// macros only\n#pragma once\n#define FT_X 1\n",
        "native/src/noise/n.cpp": "namespace ft::noise {\nnamespace {\n}\n}\nnamespace ft::noise::detail {\n}\n",
        "native/src/terrain/t.cpp": '#include "noise/fbm.hpp"\n#include "fracterra/terrain.h"\n',
        "native/src/subdiv/s.cpp": "#include <opensubdiv/far/topologyRefiner.h>\nnamespace ft::subdiv {}\n",
        "native/src/povray/p.cpp": "namespace ft::pov {\n}\n",
        "native/src/noise/rows.inc": "struct Row {};\n",  # a fragment, expanded in its includer's namespace
        "native/src/capi/x.cpp": 'extern "C" int ft_x() { return 0; }\n',
        "native/cli/c.cpp": '#include "povray/scene.hpp"\n#include <CLI/CLI.hpp>\nnamespace ft::cli {}\n',
    }
    bad = {
        "native/src/core/up.hpp": ('#include "terrain/terrain.hpp"\n', "upwards"),
        "native/src/io/side.hpp": ('#include "analysis/clouds.hpp"\n', "sideways"),
        "native/src/noise/pub.hpp": ('#include "fracterra/terrain.h"\n', "belongs to terrain/"),
        "native/src/mesh/all.hpp": ('#include "fracterra/fracterra.h"\n', "umbrella"),
        "native/cli/abi.cpp": ('#include "capi/guard.hpp"\n', "sideways"),
        "native/src/terrain/osd.cpp": ("#include <opensubdiv/far/topologyRefiner.h>\n", "only subdiv/"),
        "native/src/newlayer/x.hpp": ('#include "core/error.hpp"\n', "without a rank"),
        "native/src/io/root.cpp": ("namespace ft {\nvoid f();\n}\n", "opens namespace ft;"),
        "native/src/analysis/other.hpp": ("namespace ft::io {\n}\n", "opens namespace ft::io"),
        "native/src/contour/bare.cpp": ("int f() { return 1; }\n", "outside namespace ft::contour"),
        "native/src/io/frag.inc": ("namespace ft::noise {\n}\n", "opens namespace ft::noise"),
    }
    with tempfile.TemporaryDirectory() as d:
        root = Path(d)
        for rel, text in good.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        found = violations(root)
        if found:
            print("self-test: a clean tree was reported:", *found, sep="\n  ")
            return 1
        # The picture: the generated one passes, one with a layer's rank changed fails.
        doc = root / PICTURE_DOC
        doc.parent.mkdir(parents=True, exist_ok=True)
        doc.write_text(f"# x\n{PICTURE_BEGIN}\n{PICTURE_END}\n")
        write_picture(doc)
        if picture_violations(root):
            print("self-test: the generated picture was reported:", *picture_violations(root), sep="\n  ")
            return 1
        doc.write_text(doc.read_text().replace("       0  core/", "       1  core/"))
        if not any("differs" in v for v in picture_violations(root)):
            print("self-test: a picture that differs from LAYERS was not reported")
            return 1
        doc.unlink()
        for rel, (text, _) in bad.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        found = violations(root)
        missed = [rel for rel, (_, word) in bad.items()
                  if not any(Path(rel).parent.name + "/" in v and word in v for v in found)]
        if missed or len(found) != len(bad):
            print("self-test: planted bad includes not reported (or extra reports):", *missed, *found, sep="\n  ")
            return 1
    print(f"self-test: all {len(bad)} planted bad includes and namespaces reported, a wrong layer picture too, "
          "the clean tree passes")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[1])
    ap.add_argument("--self-test", action="store_true")
    ap.add_argument("--picture", action="store_true", help="print the layer picture")
    ap.add_argument("--write-picture", action="store_true", help=f"write the picture into {PICTURE_DOC}")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    if args.picture:
        print(picture(), end="")
        return 0
    if args.write_picture:
        write_picture(args.root / PICTURE_DOC)
        return 0
    found = violations(args.root) + picture_violations(args.root)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} include(s) or namespace(s) against the layer order (scripts/check_layers.py)")
        return 1
    print("layers: every include points downwards, every file is in its layer's namespace")
    return 0


if __name__ == "__main__":
    sys.exit(main())
