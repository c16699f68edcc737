#!/usr/bin/env python3
"""Checks that the native code's includes point only downwards.

native/src/ is layered by capability, one folder per layer; native/cli/ is the
`fracterra` tool. A file may include a project header of its own layer or of
a layer of lower rank, never one of the same rank (sideways) or higher
(upwards). The ranks are the README's layer picture:

    0  core/                                   rng, errors, heightfield, buffers, images
    1  io/ noise/ contour/ mesh/ preview/      file formats, noise bases, level sets,
       analysis/                               grid meshes, relief, measures (H, D, stats)
    2  terrain/                                terrains and the 1D Voss profile (uses noise/)
    3  polyline/                               polylines (the profile method uses terrain/;
                                               the FPL study uses analysis/)
       tiles/                                  tile sets of terrains larger than memory
                                               (windows of terrain/, files through io/)
    4  subdiv/ povray/                         OpenSubdiv; POV-Ray scenes (use io/)
       erosion/                                fluvial, hydraulic, thermal erosion; flow graphs
    5  hydrology/                              rivers, lakes and the sea (erosion/'s routing,
                                               polyline/'s FPL, contour/'s shorelines)
    6  tables/                                 the parameter tables of every layer, by kind
    7  capi/ cli/                              the C ABI (libfracterra.so) and the tool, side
                                               by side: both link the static core, neither
                                               includes the other

Public headers (`fracterra/*.h`, the C ABI) are included by capi/ and cli/, and
by the layer a header is named after (terrain/ includes fracterra/terrain.h for
its params struct); `fracterra/fracterra.h` (all of them) only by capi/ and
cli/; a header named after no layer (core.h: status codes) by anyone.
Third-party headers with one home: OpenSubdiv only in subdiv/, CLI11 only in
cli/.

A folder that is not in the table is an error too: a new layer gets its rank
here and in the README. Usage:

    scripts/check_layers.py [--root DIR]     # exit 1 and one line per violation
    scripts/check_layers.py --self-test      # the check catches planted bad includes
"""

import argparse
import re
import sys
import tempfile
from pathlib import Path

RANK = {
    "core": 0,
    "io": 1, "noise": 1, "contour": 1, "mesh": 1, "preview": 1, "analysis": 1,
    "terrain": 2,
    "polyline": 3,
    "subdiv": 4, "povray": 4,
    # Ranked ahead for layers being added on other branches (DEM refinement uses
    # terrain/; erosion uses analysis/); add them to the README's picture on landing.
    "refine": 3, "erosion": 4,
    "hydrology": 5,  # rivers, lakes, the sea: erosion/'s flow graph, polyline/'s FPL, contour/
    "tiles": 3,  # tile sets: windows of terrain/ written through io/
    "tables": 6,  # every capability's parameter table, by kind
    "capi": 7, "cli": 7,
}
TOP = {"capi", "cli"}  # may include any public header
# Third-party include prefixes and the only layers that may include them.
THIRD_PARTY_HOME = {"opensubdiv/": {"subdiv"}, "CLI/": {"cli"}}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SUFFIXES = {".h", ".hpp", ".cpp", ".inc", ".ipp"}


def layer_of(path, root):
    """The layer of a source file: cli for native/cli, else its folder in native/src."""
    rel = path.relative_to(root / "native")
    return "cli" if rel.parts[0] == "cli" else rel.parts[1]


def violations(root):
    """One message per include that points upwards or sideways (or into an unknown layer)."""
    out = []
    files = sorted(p for d in (root / "native" / "src", root / "native" / "cli") if d.is_dir()
                   for p in d.rglob("*") if p.suffix in SUFFIXES and p.is_file())
    for folder in sorted({layer_of(p, root) for p in files} - set(RANK)):
        out.append(f"native/src/{folder}/: a layer without a rank; give it one in scripts/check_layers.py "
                   "and in the README's layer picture")
    for path in files:
        layer = layer_of(path, root)
        if layer not in RANK:
            continue
        where = path.relative_to(root)
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
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


def self_test():
    """Plants one bad include of each kind in a scratch tree and checks each is reported,
    and that the same tree without them passes."""
    good = {
        "native/src/core/a.hpp": '#include "core/b.hpp"\n#include "fracterra/core.h"\n',
        "native/src/terrain/t.cpp": '#include "noise/fbm.hpp"\n#include "fracterra/terrain.h"\n',
        "native/src/subdiv/s.cpp": "#include <opensubdiv/far/topologyRefiner.h>\n",
        "native/cli/c.cpp": '#include "povray/scene.hpp"\n#include <CLI/CLI.hpp>\n',
    }
    bad = {
        "native/src/core/up.hpp": ('#include "terrain/terrain.hpp"\n', "upwards"),
        "native/src/io/side.hpp": ('#include "analysis/clouds.hpp"\n', "sideways"),
        "native/src/noise/pub.hpp": ('#include "fracterra/terrain.h"\n', "belongs to terrain/"),
        "native/src/mesh/all.hpp": ('#include "fracterra/fracterra.h"\n', "umbrella"),
        "native/cli/abi.cpp": ('#include "capi/guard.hpp"\n', "sideways"),
        "native/src/terrain/osd.cpp": ("#include <opensubdiv/far/topologyRefiner.h>\n", "only subdiv/"),
        "native/src/newlayer/x.hpp": ('#include "core/error.hpp"\n', "without a rank"),
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
        for rel, (text, _) in bad.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        found = violations(root)
        missed = [rel for rel, (_, word) in bad.items()
                  if not any(Path(rel).parent.name + "/" in v and word in v for v in found)]
        if missed or len(found) != len(bad):
            print("self-test: planted bad includes not reported (or extra reports):", *missed, *found, sep="\n  ")
            return 1
    print(f"self-test: all {len(bad)} planted bad includes reported, the clean tree passes")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[1])
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    found = violations(args.root)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} include(s) against the layer order (scripts/check_layers.py)")
        return 1
    print("layers: every include points downwards")
    return 0


if __name__ == "__main__":
    sys.exit(main())
