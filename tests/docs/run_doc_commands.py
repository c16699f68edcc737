#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs every example command of the README and the user guides, as written.

A guide's code blocks (indented by four spaces, or fenced) hold two kinds of
lines that start with `fracterra`: examples, which must run as written, and
synopses, which show a command's form (`a|b` for a choice, `[...]` for what
is optional, `...` for the rest, upper-case placeholders such as FILE or
DIR). Synopses are skipped; every example runs, in the order of its
document, in one scratch folder per document (so an example may read what
an earlier one of the same document wrote), with the built `fracterra` first
on PATH. Python blocks that `import fracterra` run too, with the built
package. A failure prints the document, the line and the command's stderr.

Usage: run_doc_commands.py --cli build/native/fracterra --python-path DIR [--only NAME] [DOC ...]
"""

import argparse
import math
import os
import re
import resource
import shlex
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# The documents whose examples run: the README, the user guides, the Python guide.
DEFAULT_DOCS = ["README.md", *sorted(str(p.relative_to(ROOT)) for p in (ROOT / "docs").glob("*.md")),
                "python/README.md"]
COMMANDS = ("fracterra ", "python3 -m fracterra.")
# A placeholder: a word of two or more capitals that is not a flag value such as WxH or an EPSG code.
PLACEHOLDER = re.compile(r"(?<![\w-])(FILE|DIR|TERRAIN|PRESET|FACE|X0|Y0|N|K|H|S|A|F|L|M|T|W|WxH|SECONDS)(?![\w])")
TIMEOUT = 300
# Examples that do not run here, each with its reason: (document, a regular
# expression the command matches, why). Every test run runs the rest, so each
# is kept to a few seconds of CPU (the script prints each one's); heavier ones
# are left to the tests named in their reason. A rule that matches no example
# fails the run, so a stale one is noticed.
NOT_RUN = (
    ("README.md", r"^fracterra tiles --levels 13 ", "an 8193^2 tile set (16 s of CPU); tests/tiles cuts small sets"),
    ("docs/engines.md", r"^fracterra tiles .*--levels 13 ", "an 8193^2 tile set (12 s of CPU); tests/tiles cuts small sets"),
    ("docs/scale.md", r"^fracterra tiles .*--levels 13 .*--erode",
     "an eroded 8193^2 tile set: minutes of CPU; tests/tiles erodes small sets"),
    ("docs/planets.md", r"--render globe|--render mid\.png",
     "POV-Ray renders of a whole globe: 10 s to over a minute of CPU each; tests/povray renders planets"),
    ("docs/planets.md", r"--patch 4,4194304,4194304,4096,4096",
     "a 4096^2 patch (5 s of CPU); the 1024^2 patch above runs"),
    ("docs/planets.md", r"--threads 1 ", "the one-thread timings of the page's measurements (4-5 s of CPU each)"),
    ("docs/polyline.md", r"^fracterra study fpl .*--depth 4,6,8,10,12 ",
     "30 studies of 100 polylines (7 s of CPU); README's smaller study runs"),
    ("docs/povray.md", r"demo-out/", "the demo's own steps: examples/demo.sh makes demo-out/ and its polylines"),
)


def blocks(text):
    """(line number, block lines) of each code block: indented by 4 or fenced."""
    lines = text.splitlines()
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("```"):
            lang = line[3:].strip()
            start, body = i + 1, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            out.append((start + 1, lang, body))
        elif line.startswith("    ") and (i == 0 or not lines[i - 1].strip()):
            start, body = i, []
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                body.append(lines[i][4:])
                i += 1
            while body and not body[-1].strip():
                body.pop()
            out.append((start + 1, "", body))
            continue
        i += 1
    return out


def joined(body):
    """Lines with their backslash continuations joined, each with its offset in the block."""
    out, cur, at = [], "", None
    for k, line in enumerate(body):
        if at is None:
            at = k
        if line.rstrip().endswith("\\"):
            cur += line.rstrip()[:-1] + " "
            continue
        out.append((at, cur + line))
        cur, at = "", None
    return out


def unquoted(command):
    """The command with its quoted strings blanked (a `;` or `|` inside quotes is data)."""
    return re.sub(r'"[^"]*"|\'[^\']*\'', '""', command)


def is_synopsis(command):
    bare = unquoted(command.split("  #")[0])
    return ("|" in bare or "[" in bare or "..." in bare or bool(PLACEHOLDER.search(bare)))


def not_run(doc, text):
    """The reason an example of doc does not run here, or None."""
    return next((why for d, pattern, why in NOT_RUN if d == doc and re.search(pattern, text)), None)


def examples(doc):
    """(line, kind, text) of each example in doc: kind "shell" or "python"."""
    text = (ROOT / doc).read_text()
    out = []
    for start, lang, body in blocks(text):
        if lang.startswith("python") or (body and body[0].startswith("import fracterra")):
            if any("import fracterra" in l for l in body):
                out.append((start, "python", "\n".join(body)))
            continue
        for offset, command in joined(body):
            command = command.strip()
            if command.startswith(COMMANDS) and not is_synopsis(command):
                out.append((start + offset, "shell", command.split("  #")[0].strip()))
    return out


# What the guides' examples read without making it first (a user's own files):
# made once, small, and copied into every document's scratch folder before its
# first example (an example that writes one of them replaces it). The
# repository's examples/ is linked in, as the examples run from its root.
FIXTURES = (
    ("t.png", "fracterra terrain --levels 7 --seed 7 --out t.png"),
    ("terrain.png", "fracterra terrain --levels 7 --seed 3 --out terrain.png"),
    ("coarse.png", "fracterra terrain --levels 3 --seed 5 --out coarse.png"),
    ("bolt.csv", 'fracterra polyline --method fpl3d --base "0,0,1;0.1,0,0" --depth 6 --out bolt.csv'),
    ("coast.csv", 'fracterra polyline --method fpl --base "0,0;1,0" --depth 6 --out coast.csv'),
    ("rivers.json", "fracterra rivers --in t.png --out rivers.json"),
    ("carved.npy", "fracterra terrain --levels 7 --seed 7 --rivers r.json --out carved.npy"),  # and r.json
    ("rules.json", "fracterra splat --print-rules > rules.json"),
    ("scene.pov", "fracterra terrain --levels 5 --out scene.png --pov scene.pov"),
)
# Greyscale masks (white 1): 8-bit PNGs that a user paints.
MASKS = ("m.png", "r.png", "outline.png")


def grey_png(path, side=33):
    """A side x side 8-bit greyscale PNG: a bright disc fading to black at the edges."""
    import struct
    import zlib

    def grey(x, y):
        r = math.hypot(x / (side - 1) - 0.5, y / (side - 1) - 0.5)
        return max(0, min(255, int(255 * (1.5 - 2.2 * r))))

    rows = b"".join(b"\0" + bytes(grey(x, y) for x in range(side)) for y in range(side))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0)  # 8-bit, greyscale
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) +
                     chunk(b"IEND", b""))


def make_fixtures(folder, env):
    folder.mkdir(parents=True, exist_ok=True)
    for name, command in FIXTURES:
        subprocess.run(["bash", "-c", command], cwd=folder, env=env, check=True, capture_output=True)
    for name in MASKS:
        grey_png(folder / name)
    return folder


def children_cpu():
    """CPU seconds (user + sys) of the finished child processes so far: a loaded machine stretches
    wall time, not this."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def staged_package(scratch, cli, library):
    """The fracterra package as the wheel lays it out (python/CMakeLists.txt), from the source:
    python/fracterra with the add-on's core/ inside and its params.json; the library is
    FRACTERRA_LIBRARY's."""
    import shutil
    top = scratch / "python"
    shutil.copytree(ROOT / "python" / "fracterra", top / "fracterra",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "blender_addon" / "fracterra" / "core", top / "fracterra" / "core",
                    ignore=shutil.ignore_patterns("__pycache__"))
    subprocess.run([str(cli), "params", "--json", "--out", str(top / "fracterra" / "core" / "params.json")],
                   check=True)
    return top


def run(doc, items, env, keep, timeout=TIMEOUT, fixtures=None):
    import shutil
    failures = []
    scratch = Path(tempfile.mkdtemp(prefix="doc-" + Path(doc).stem + "-"))
    if fixtures:
        shutil.copytree(fixtures, scratch, dirs_exist_ok=True)
    (scratch / "examples").symlink_to(ROOT / "examples")
    for line, kind, text in items:
        why = not_run(doc, text)
        if why:
            print(f"skip             {doc}:{line}  {text.splitlines()[0]}  (not run: {why})", flush=True)
            continue
        t0, cpu0 = time.monotonic(), children_cpu()
        if kind == "python":
            args = [sys.executable, "-c", text]
        else:
            args = ["bash", "-c", text]
        # In a session of its own: on a timeout the whole group goes (a command's
        # POV-Ray child kept the pipes open, and the wait, past the timeout).
        p = subprocess.Popen(args, cwd=scratch, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, start_new_session=True)
        try:
            out, errout = p.communicate(timeout=timeout)
            ok, err = p.returncode == 0, (errout or out)[-2000:]
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            ok, err = False, f"timed out after {timeout} s"
        took, cpu = time.monotonic() - t0, children_cpu() - cpu0
        shown = text.splitlines()[0] + (" ..." if "\n" in text else "")
        print(f"{'ok  ' if ok else 'FAIL'} {took:6.1f} s {cpu:6.1f} s CPU  {doc}:{line}  {shown}", flush=True)
        if not ok:
            failures.append(f"{doc}:{line}: {shown}\n{err}")
    if not keep:
        subprocess.run(["rm", "-rf", str(scratch)])
    return failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cli", type=Path, required=True, help="the built fracterra")
    ap.add_argument("--python-path", type=Path, help="a folder holding the fracterra package with its library")
    ap.add_argument("--library", type=Path,
                    help="without --python-path: the built libfracterra, with the package staged from the source")
    ap.add_argument("--keep", action="store_true", help="keep the scratch folders")
    ap.add_argument("--list", action="store_true", help="list the examples and synopses, run nothing")
    ap.add_argument("--timeout", type=float, default=TIMEOUT, help="seconds per example")
    ap.add_argument("docs", nargs="*", default=DEFAULT_DOCS)
    args = ap.parse_args()
    if args.list:
        for doc in args.docs:
            for line, kind, text in examples(doc):
                why = not_run(doc, text)
                print(f"{doc}:{line}: [{kind}] {text.splitlines()[0]}" + (f"  (not run: {why})" if why else ""))
        return 0
    every = {doc: examples(doc) for doc in DEFAULT_DOCS}
    stale = [(d, pattern) for d, pattern, _ in NOT_RUN
             if not any(re.search(pattern, text) for _, _, text in every.get(d, []))]
    if stale:
        print("NOT_RUN rules that match no example (remove them):", *stale, sep="\n  ")
        return 1
    env = dict(os.environ)
    bindir = Path(tempfile.mkdtemp(prefix="doc-bin-"))
    (bindir / "fracterra").symlink_to(args.cli.resolve())
    env["PATH"] = f"{bindir}:{env['PATH']}"
    if not args.python_path and args.library:
        args.python_path = staged_package(bindir, args.cli, args.library)
        env["FRACTERRA_LIBRARY"] = str(args.library.resolve())
    if args.python_path:
        env["PYTHONPATH"] = f"{args.python_path.resolve()}:{env.get('PYTHONPATH', '')}"
    failures, count, skipped = [], 0, 0
    try:
        fixtures = make_fixtures(bindir / "fixtures", env)
        for doc in args.docs:
            items = examples(doc)
            skipped += sum(not_run(doc, text) is not None for _, _, text in items)
            count += len(items)
            failures += run(doc, items, env, args.keep, args.timeout, fixtures)
    finally:
        if not args.keep:  # the CLI's link, the staged package, the fixtures
            subprocess.run(["rm", "-rf", str(bindir)])
    if failures:
        print(f"\n{len(failures)} of {count - skipped} documented examples failed:\n")
        print("\n\n".join(failures))
        return 1
    print(f"all {count - skipped} documented examples ran ({skipped} not run, each saying why)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
