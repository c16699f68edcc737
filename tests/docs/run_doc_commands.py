#!/usr/bin/env python3
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
import os
import re
import shlex
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


def run(doc, items, env, keep):
    failures = []
    scratch = Path(tempfile.mkdtemp(prefix="doc-" + Path(doc).stem + "-"))
    for line, kind, text in items:
        t0 = time.monotonic()
        if kind == "python":
            args = [sys.executable, "-c", text]
        else:
            args = ["bash", "-c", text]
        try:
            p = subprocess.run(args, cwd=scratch, env=env, capture_output=True, text=True, timeout=TIMEOUT)
            ok, err = p.returncode == 0, (p.stderr or p.stdout)[-2000:]
        except subprocess.TimeoutExpired:
            ok, err = False, f"timed out after {TIMEOUT} s"
        took = time.monotonic() - t0
        shown = text.splitlines()[0] + (" ..." if "\n" in text else "")
        print(f"{'ok  ' if ok else 'FAIL'} {took:6.1f} s  {doc}:{line}  {shown}")
        if not ok:
            failures.append(f"{doc}:{line}: {shown}\n{err}")
    if not keep:
        subprocess.run(["rm", "-rf", str(scratch)])
    return failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cli", type=Path, required=True, help="the built fracterra")
    ap.add_argument("--python-path", type=Path, help="a folder holding the fracterra package with its library")
    ap.add_argument("--keep", action="store_true", help="keep the scratch folders")
    ap.add_argument("--list", action="store_true", help="list the examples and synopses, run nothing")
    ap.add_argument("docs", nargs="*", default=DEFAULT_DOCS)
    args = ap.parse_args()
    if args.list:
        for doc in args.docs:
            for line, kind, text in examples(doc):
                print(f"{doc}:{line}: [{kind}] {text.splitlines()[0]}")
        return 0
    env = dict(os.environ)
    bindir = Path(tempfile.mkdtemp(prefix="doc-bin-"))
    (bindir / "fracterra").symlink_to(args.cli.resolve())
    env["PATH"] = f"{bindir}:{env['PATH']}"
    if args.python_path:
        env["PYTHONPATH"] = f"{args.python_path.resolve()}:{env.get('PYTHONPATH', '')}"
    failures, count = [], 0
    for doc in args.docs:
        items = examples(doc)
        count += len(items)
        failures += run(doc, items, env, args.keep)
    if failures:
        print(f"\n{len(failures)} of {count} documented examples failed:\n")
        print("\n\n".join(failures))
        return 1
    print(f"all {count} documented examples ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
