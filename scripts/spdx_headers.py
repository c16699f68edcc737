#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Gives every source file of the project its SPDX licence line,
`SPDX-License-Identifier: GPL-3.0-or-later` (LICENSE), as a comment in the
file's own syntax: first, or after a `#!` line and a Python encoding line.

    scripts/spdx_headers.py [--root DIR]           add the line where it is missing
    scripts/spdx_headers.py --check [--root DIR]   list the files without it; exit 1 if any
    scripts/spdx_headers.py --self-test            the check finds a planted file, the fix fixes it

Source files are C, C++, Python, shell, CMake, TOML and POV-Ray files, tracked
by git or not yet (`git ls-files --cached --others --exclude-standard`, so
build trees and ignored files are left out); outside a git checkout, the tree
without build*/ and hidden directories. Data (pictures, grids, fuzz inputs,
and the EXCLUDED folders' files) and Markdown carry no header. ctest runs --check (tests/licence)."""

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

LICENCE = "GPL-3.0-or-later"
TAG = "SPDX-License-Identifier:"
LINE_COMMENT = {
    ".c": "//", ".h": "//", ".cpp": "//", ".hpp": "//", ".cc": "//",
    ".inc": "//", ".pov": "//",
    ".py": "#", ".sh": "#", ".cmake": "#", ".toml": "#",
}
NAMED = {"CMakeLists.txt": "#"}
# How far into a file the line may be (after a shebang, an encoding line).
HEAD_LINES = 5
# Folders of files that have a source file's name but are data, and why.
EXCLUDED = {
    "blender_addon/fracterra/presets/": "Blender operator presets, copied into the user's preset folder as theirs",
    "tests/blender/data/": "test inputs known byte for byte (the retired presets' SHA-256, common/presets.py)",
}


def comment_of(path: Path):
    return NAMED.get(path.name) or LINE_COMMENT.get(path.suffix)


def source_files(root: Path):
    try:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                             capture_output=True, check=True).stdout
        names = [n for n in out.decode().split("\0") if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
        for top, dirs, files in os.walk(root):
            rel = Path(top).relative_to(root)
            dirs[:] = [d for d in dirs if not d.startswith(".") and not (rel == Path(".") and d.startswith("build"))]
            names += [str(rel / f) for f in files]
    for name in sorted(names):
        if any(Path(name).as_posix().startswith(folder) for folder in EXCLUDED):
            continue
        path = root / name
        if comment_of(path) and path.is_file():  # a deleted but tracked file is not there
            yield path


def has_header(text: str, comment: str) -> bool:
    line = f"{comment} {TAG} {LICENCE}"
    return any(l.strip() == line for l in text.splitlines()[:HEAD_LINES])


def with_header(text: str, comment: str) -> str:
    lines = text.splitlines(keepends=True)
    at = 0
    if lines and lines[0].startswith("#!"):
        at = 1
    if at < len(lines) and re.match(r"#.*coding[:=]", lines[at]):
        at += 1
    newline = "\r\n" if lines and lines[0].endswith("\r\n") else "\n"
    lines.insert(at, f"{comment} {TAG} {LICENCE}{newline}")
    return "".join(lines)


def missing(root: Path):
    return [p for p in source_files(root)
            if not has_header(p.read_text(encoding="utf-8", errors="replace"), comment_of(p))]


def add(root: Path) -> int:
    files = missing(root)
    for p in files:
        text = p.read_text(encoding="utf-8")
        mode = p.stat().st_mode
        p.write_text(with_header(text, comment_of(p)), encoding="utf-8")
        os.chmod(p, mode)
    print(f"spdx_headers: added the licence line to {len(files)} file(s)")
    return 0


def check(root: Path) -> int:
    files = missing(root)
    for p in files:
        print(f"{p.relative_to(root)}: no '{TAG} {LICENCE}' in its first {HEAD_LINES} lines")
    if files:
        print(f"spdx_headers: {len(files)} source file(s) without the licence line; "
              "scripts/spdx_headers.py adds it", file=sys.stderr)
        return 1
    print(f"spdx_headers: every source file names {LICENCE}")
    return 0


def self_test() -> int:
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / "a.cpp").write_text("// A file.\nint x;\n")
        (root / "b.sh").write_text("#!/bin/sh\necho b\n")
        (root / "c.py").write_text(f'# {TAG} {LICENCE}\n"""Has it."""\n')
        (root / "e.py").write_text(f'"""Names {TAG} {LICENCE} in its text only."""\n')
        (root / "d.png").write_bytes(b"\x89PNG")  # data: no header
        (root / "tests/blender/data").mkdir(parents=True)
        (root / "tests/blender/data/old.py").write_text("import bpy\n")  # an EXCLUDED folder
        found = sorted(p.name for p in missing(root))
        assert found == ["a.cpp", "b.sh", "e.py"], found
        add(root)
        assert not missing(root)
        assert (root / "b.sh").read_text().startswith(f"#!/bin/sh\n# {TAG} {LICENCE}\n")
        assert (root / "a.cpp").read_text() == f"// {TAG} {LICENCE}\n// A file.\nint x;\n"
    print("spdx_headers: self-test passed")
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    ap.add_argument("--check", action="store_true", help="only list the files without the line")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    return check(a.root.resolve()) if a.check else add(a.root.resolve())


if __name__ == "__main__":
    sys.exit(main())
