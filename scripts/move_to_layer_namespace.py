#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Moves a layer, native/src/X/, from the plain namespace `ft` into `ft::X` and
qualifies its names in every other C++ file (other layers, cli/, capi/,
native/bench, tests/). Used for every layer (issue 25), terrain/ and polyline/
last; kept for code brought in from older branches (run it again: it also
qualifies new callers of a layer already moved).

    scripts/move_to_layer_namespace.py X [EXTRA_NAME ...]

What it does, on code only (comments, strings and #include lines are left):
- in X/: `namespace ft {` -> `namespace ft::X {`, `ft::detail` -> `ft::X::detail`,
  and the closing `}  // namespace ...` comments;
- everywhere: `ft::name` -> `ft::X::name`, `[ft::]detail::name` ->
  `[ft::]X::detail::name` for every name X/'s headers declare at namespace
  scope (ctags: types, functions, constants, unscoped enumerators);
- outside X/: an unqualified use of such a name -> `X::name` (a call, a type,
  a constant), unless the name follows `.`, `->` or `::`, is followed by `.`,
  `->` or `[`, or is being declared (`Type name(`); a file with a local
  variable of the same name (`auto fbm = ...`, `T& fbm,`) is left alone for
  that name, so the compiler points at any call there to qualify by hand.
Then: build, fix what the compiler names, remove X from NAMESPACE_TODO and
run scripts/check_layers.py. Names given as EXTRA_NAME are qualified too
(for example ones ctags misses). It edits files in place: run it on a clean tree.
"""
import re
import subprocess
import sys
from pathlib import Path

root = Path(__file__).resolve().parents[1]
X = sys.argv[1]
layer_dir = root / "native" / "src" / X
KEYWORDS = {"return", "else", "throw", "case", "co_return", "co_yield", "new", "and", "or",
            "not", "do", "delete", "sizeof", "decltype", "noexcept"}

# Names declared at namespace scope ft or ft::detail in the layer's headers.
out = subprocess.run(["ctags", "-x", "--c++-kinds=+p+e-m-l", "--language-force=c++", "--extras=-q",
                      "--_xformat=%N %K %s"] + [str(p) for p in sorted(layer_dir.glob("*.hpp"))],
                     capture_output=True, text=True, check=True).stdout
top, det = set(), set()
for line in out.splitlines():
    parts = line.split()
    if len(parts) < 3:
        continue
    name, kind, scope = parts[0], parts[1], parts[2]
    if kind in ("macro", "namespace") or name.startswith("operator") or name.startswith("~"):
        continue
    if kind == "enumerator":
        enum = scope.rsplit("::", 1)
        if len(enum) == 2 and enum[0] in ("ft", "ft::detail", f"ft::{X}", f"ft::{X}::detail") and not any(
                re.search(r"enum\s+(class|struct)\s+%s\b" % enum[1], h.read_text()) for h in layer_dir.glob("*.hpp")):
            (top if enum[0] in ("ft", f"ft::{X}") else det).add(name)
        continue
    if scope in ("ft", f"ft::{X}"):  # (ft::X: run again after a merge brought new callers)
        top.add(name)
    elif scope in ("ft::detail", f"ft::{X}::detail"):
        det.add(name)
extra = set(sys.argv[2:])
top |= extra
print("top:", sorted(top))
print("detail:", sorted(det))

files = [p for d in ("native/src", "native/cli", "native/bench", "tests/native", "tests/fuzz",
                     "tests/povray", "tests/raster")
         for p in (root / d).rglob("*") if p.suffix in (".cpp", ".hpp", ".h") and p.is_file()]

TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|R"(\w*)\((?:.|\n)*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|^\s*#\s*include[^\n]*',
                   re.S | re.M)


def code_segments(text):
    """Yields (is_code, chunk)."""
    pos = 0
    for m in TOKEN.finditer(text):
        if m.start() > pos:
            yield True, text[pos:m.start()]
        yield False, m.group(0)
        pos = m.end()
    if pos < len(text):
        yield True, text[pos:]


def is_function_like(name):
    return name[0].islower() and not re.match(r"k[A-Z]", name)


def rewrite_code(code, own, full):
    # ft::name -> ft::X::name ; ft::detail::name -> ft::X::detail::name
    names = "|".join(sorted(top, key=len, reverse=True))
    dnames = "|".join(sorted(det, key=len, reverse=True))
    if dnames:
        code = re.sub(r"(?<![\w:])(ft::)?detail::(%s)\b" % dnames,
                      lambda m: (m.group(1) or "") + f"{X}::detail::" + m.group(2), code)
    if names:
        code = re.sub(r"(?<![\w:])ft::(%s)\b" % names, lambda m: f"ft::{X}::" + m.group(1), code)
    if own or not names:
        return code
    local = full
    names = "|".join(sorted(top - local, key=len, reverse=True))
    if not names:
        return code

    def unq(m):
        name = m.group(2)
        before = code[max(0, m.start(2) - 120):m.start(2)]
        after = code[m.end(2):m.end(2) + 120]
        if re.search(r"(\.|->|::|~)\s*$", before):
            return m.group(0)
        if re.match(r"\s*(\.|->|\[)", after):
            return m.group(0)
        if re.search(r"\bTEST(_F|_P)?\(\s*$", before):
            return m.group(0)  # a googletest suite named after the type
        if is_function_like(name):
            if not re.match(r"\s*\(", after) and not re.search(r"&\s*$", before):
                return m.group(0)
            pm = re.search(r"([\w>&*]+)\s+$", before)
            if pm and pm.group(1) not in KEYWORDS and re.match(r"\w", pm.group(1)):
                return m.group(0)  # a declaration: `Type name(...)`
        return m.group(1) + f"{X}::" + name

    return re.sub(r"(^|[^\w:.>~])(%s)\b" % names, unq, code)


changed = []
for p in files:
    own = p.parent == layer_dir
    text = p.read_text()
    local = {n for n in top if re.search(r"\bauto\s+%s\s*=" % n, text) or
             re.search(r"[&*]\s*%s\s*[,)=;]" % n, text)}
    new = "".join(rewrite_code(c, own, local) if is_code else c for is_code, c in code_segments(text))
    if own:
        new = re.sub(r"^namespace ft::detail \{", f"namespace ft::{X}::detail {{", new, flags=re.M)
        new = re.sub(r"^\}  // namespace ft::detail$", f"}}  // namespace ft::{X}::detail", new, flags=re.M)
        new = re.sub(r"^namespace ft \{", f"namespace ft::{X} {{", new, flags=re.M)
        new = re.sub(r"^\}  // namespace ft$", f"}}  // namespace ft::{X}", new, flags=re.M)
    if new != text:
        p.write_text(new)
        changed.append(str(p.relative_to(root)))
print("changed:", *changed, sep="\n  ")
