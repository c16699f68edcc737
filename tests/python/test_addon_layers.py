# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on's modules import in one direction only. blender/ is split by role
into folders ranked common/ < build/ < ui/ < ops/: a module imports only from
its own folder or a lower one, never in a circle, and never inside a function
to dodge one (blender/ and core/ alike). Panels and menus name operators by
id string, and the shared operator helpers are defined once. Read from the
source with ast: no Blender needed."""

import ast
import functools
from pathlib import Path

import pytest

ADDON_DIR = Path(__file__).resolve().parents[2] / "blender_addon" / "fracterra"
BLENDER_DIR = ADDON_DIR / "blender"
CORE_DIR = ADDON_DIR / "core"
# The folders of blender/ by rank: each imports only its own rank or lower ones.
RANKS = {"common": 0, "build": 1, "ui": 2, "ops": 3}
SHARED_NAMES = {"SettingsError", "REPORTED"}


def module_name(path, root):
    """'ui.panels' for blender/ui/panels.py, 'params' for core/params.py, '' for a package's __init__."""
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


@functools.lru_cache(maxsize=None)
def modules(root=BLENDER_DIR):
    return {module_name(p, root): ast.parse(p.read_text(), str(p)) for p in sorted(root.rglob("*.py"))}


def package_of(name, root):
    """The package a module's relative imports start from (a package's __init__ is its own)."""
    path = root.joinpath(*name.split(".")) if name else root
    return name if (path / "__init__.py").is_file() else name.rpartition(".")[0]


def add_on_imports(name, tree, root, top_level_only):
    """The modules of `root` (blender/ or core/) that module `name` imports
    (`from . import x`, `from ..build.mesh import y`), as names like 'build.mesh'."""
    nodes = tree.body if top_level_only else ast.walk(tree)
    known = set(modules(root))
    out = set()
    for node in nodes:
        if not isinstance(node, ast.ImportFrom) or node.level == 0:
            continue
        base = package_of(name, root).split(".") if package_of(name, root) else []
        up = node.level - 1
        if up > len(base):
            continue  # above root: core from blender/, or the add-on's own package
        base = base[:len(base) - up]
        target = ".".join(base + (node.module.split(".") if node.module else []))
        if node.module is None or target not in known:
            for alias in node.names:
                full = f"{target}.{alias.name}" if target else alias.name
                if full in known:
                    out.add(full)
                elif target in known:
                    out.add(target)
        else:
            out.add(target)
    out.discard(name)
    return out


def is_package(name, root):
    return (root.joinpath(*name.split(".")) / "__init__.py").is_file() if name else True


@functools.lru_cache(maxsize=None)
def graph(root=BLENDER_DIR):
    """{module: the add-on modules it imports} (packages' __init__ files left out)."""
    return {name: add_on_imports(name, tree, root, top_level_only=False)
            for name, tree in modules(root).items() if not is_package(name, root)}


def find_cycle(edges):
    """One import cycle as a list of modules, or None."""
    state = {}

    def visit(node, path):
        state[node] = "open"
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == "open":
                return path[path.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt, path + [nxt])
                if found:
                    return found
        state[node] = "done"
        return None

    for start in sorted(edges):
        if start not in state:
            found = visit(start, [start])
            if found:
                return found
    return None


def rank(name):
    return RANKS[name.split(".")[0]]


def test_every_blender_module_sits_in_a_ranked_folder():
    loose = [name for name in graph() if "." not in name or name.split(".")[0] not in RANKS]
    assert not loose, f"modules outside common/, build/, ui/, ops/: {loose}"


def test_the_role_folders_hold_their_modules():
    names = set(graph())
    assert {"ops.terrain", "ops.polyline", "ui.panels", "ui.menus", "ui.properties", "common.preferences",
            "common.reporting", "common.jobs", "build.terrain", "build.mesh"} <= names


@pytest.mark.parametrize("name", sorted(graph()))
def test_a_blender_module_imports_only_its_rank_or_lower(name):
    upward = {m for m in graph()[name] if rank(m) > rank(name)}
    assert not upward, f"{name} imports {sorted(upward)}, a folder ranked above its own ({list(RANKS)})"


def test_the_rank_check_sees_an_upward_import():
    tree = ast.parse("from ..ops.terrain import FRACTERRA_OT_terrain_add\n")
    imported = add_on_imports("build.terrain", tree, BLENDER_DIR, top_level_only=True)
    assert imported == {"ops.terrain"} and rank("ops.terrain") > rank("build.terrain")


@pytest.mark.parametrize("root", [BLENDER_DIR, CORE_DIR], ids=["blender", "core"])
def test_no_import_cycle(root):
    assert find_cycle(graph(root)) is None


def test_the_cycle_finder_finds_a_cycle():
    assert find_cycle({"panels": {"props"}, "props": {"terrain_build"}, "terrain_build": {"panels"}}) == \
        ["panels", "props", "terrain_build", "panels"]


@pytest.mark.parametrize("root,name", [(r, n) for r in (BLENDER_DIR, CORE_DIR) for n in sorted(modules(r))],
                         ids=lambda v: v.name if isinstance(v, Path) else v)
def test_imports_of_the_add_on_are_at_module_level(root, name):
    tree = modules(root)[name]
    late = (add_on_imports(name, tree, root, top_level_only=False)
            - add_on_imports(name, tree, root, top_level_only=True))
    assert not late, f"{root.name}/{name} imports {sorted(late)} inside a function (a late import hides a cycle)"


def unresolved_imports(name, tree, root):
    """Relative imports of module `name` naming a module or package the add-on lacks."""
    out = []
    base = package_of(name, root).split(".") if package_of(name, root) else []
    for node in ast.walk(tree):
        if not isinstance(node, ast.ImportFrom) or node.level == 0:
            continue
        up = node.level - 1
        if up > len(base):  # the add-on package itself (core from blender/) or above
            if up == len(base) + 1 and node.module is None and [a.name for a in node.names] == ["core"]:
                continue
            if up == len(base) + 1 and node.module and node.module.split(".")[0] == "core":
                target = ADDON_DIR.joinpath(*node.module.split("."))
                if not (target.with_suffix(".py").is_file() or (target / "__init__.py").is_file()):
                    out.append(node.module)
                continue
            out.append("." * node.level + (node.module or ""))
            continue
        parts = base[:len(base) - up] + (node.module.split(".") if node.module else [])
        target = root.joinpath(*parts)
        if node.module and not (target.with_suffix(".py").is_file() or (target / "__init__.py").is_file()):
            out.append("." * node.level + node.module)
    return out


@pytest.mark.parametrize("root,name", [(r, n) for r in (BLENDER_DIR, CORE_DIR) for n in sorted(modules(r))],
                         ids=lambda v: v.name if isinstance(v, Path) else v)
def test_every_relative_import_names_a_module_that_exists(root, name):
    assert not unresolved_imports(name, modules(root)[name], root)


def test_a_late_import_is_seen():
    tree = ast.parse("def f():\n    from .binding import library\n")
    assert add_on_imports("params", tree, CORE_DIR, top_level_only=False) == {"binding"}
    assert add_on_imports("params", tree, CORE_DIR, top_level_only=True) == set()


@pytest.mark.parametrize("name", sorted(n for n in graph() if n.startswith("ui.") or n == "common.widgets"))
def test_ui_modules_import_no_operator_module(name):
    assert not {m for m in graph()[name] if m.startswith("ops.")}, \
        f"{name} imports an operator module; use its id string"


def test_preferences_are_a_leaf():
    assert graph()["common.preferences"] <= {"common.widgets"}


def test_shared_helpers_are_defined_once_in_reporting():
    where = {}
    for name, tree in modules().items():
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                defined = {node.name}
            elif isinstance(node, ast.Assign):
                defined = {t.id for t in node.targets if isinstance(t, ast.Name)}
            else:
                continue
            for d in defined & SHARED_NAMES:
                where.setdefault(d, []).append(name)
    assert where == {n: ["common.reporting"] for n in SHARED_NAMES}
