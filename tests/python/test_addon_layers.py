"""The add-on's Blender modules import in one direction only (no circle, no
function-level import to dodge one), panels and menus name operators by id
string, and the shared operator helpers are defined once. Read from the
source with ast: no Blender needed."""

import ast
from pathlib import Path

import pytest

BLENDER_DIR = Path(__file__).resolve().parents[2] / "blender_addon" / "fracterra" / "blender"
OPERATOR_MODULES = {"terrain_ops", "polyline_ops", "measure_op", "fractalize_op", "pov_export", "dem_io_ops",
                    "tiles_import_op"}
SHARED_NAMES = {"SettingsError", "REPORTED"}


def modules():
    return {p.stem: ast.parse(p.read_text(), str(p)) for p in sorted(BLENDER_DIR.glob("*.py"))}


def sibling_imports(tree, top_level_only):
    """Names of blender/ modules a module imports (`from . import x`, `from .x import y`)."""
    nodes = tree.body if top_level_only else ast.walk(tree)
    out = set()
    for node in nodes:
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            if node.module:
                out.add(node.module.split(".")[0])
            else:
                out.update(alias.name for alias in node.names)
    return out


def graph():
    return {name: sibling_imports(tree, top_level_only=False) for name, tree in modules().items()
            if name != "__init__"}


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


def test_the_blender_modules_exist():
    names = set(modules())
    assert OPERATOR_MODULES | {"panels", "menus", "props", "prefs", "reporting", "terrain_build"} <= names


def test_no_import_cycle_among_the_blender_modules():
    assert find_cycle(graph()) is None


def test_the_cycle_finder_finds_a_cycle():
    assert find_cycle({"panels": {"props"}, "props": {"terrain_build"}, "terrain_build": {"panels"}}) == \
        ["panels", "props", "terrain_build", "panels"]


@pytest.mark.parametrize("name", sorted(p.stem for p in BLENDER_DIR.glob("*.py")))
def test_imports_of_the_add_on_are_at_module_level(name):
    tree = modules()[name]
    assert sibling_imports(tree, top_level_only=False) == sibling_imports(tree, top_level_only=True), \
        f"{name}.py imports a sibling inside a function (a late import hides a cycle)"


@pytest.mark.parametrize("name", ["panels", "menus", "prefs", "widgets", "settings_ui"])
def test_ui_modules_import_no_operator_module(name):
    assert not (graph()[name] & OPERATOR_MODULES), f"{name}.py imports an operator module; use its id string"


def test_preferences_are_a_leaf():
    assert graph()["prefs"] <= {"widgets"}


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
    assert where == {n: ["reporting"] for n in SHARED_NAMES}
