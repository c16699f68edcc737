# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared set-up of the Blender tests: install the built add-on zip into the
temporary user scripts folder (BLENDER_USER_SCRIPTS, set by ctest), enable it,
and run a unittest module; the exit code tells ctest the result.

Run as: blender -b --factory-startup --python-exit-code 1 --python <test.py> -- --zip fracterra.zip
or, in Blender 4.2+ after `blender --command extension install-file --repo user_default
--enable fracterra.zip`: blender -b --python-exit-code 1 --python <test.py> -- --installed
(the add-on is then the module bl_ext.user_default.fracterra).
"""

import argparse
import importlib
import os
import shutil
import sys
import unittest
from pathlib import Path

import addon_utils
import bpy

# The add-on's top-level module name: "fracterra" when installed as a legacy
# add-on, "bl_ext.<repo>.fracterra" as a Blender 4.2+ extension.
PACKAGE = "fracterra"


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser()
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--zip", help="the add-on zip built by CMake, installed here")
    group.add_argument("--installed", action="store_true",
                       help="the add-on is already installed and enabled as an extension")
    parser.add_argument("-k", dest="patterns", action="append",
                        help="run only the tests whose names match this pattern (as unittest's -k)")
    return parser.parse_args(argv)


def clear_scene():
    """Removes every object and mesh (the factory scene's cube, camera and light too)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def keep_renders(folder, keep, prefix=""):
    """Copies a test's renders (folder's PNGs) into `keep` (a folder an environment variable
    names; empty or None: none), each name after `prefix`, then removes folder."""
    if keep:
        os.makedirs(keep, exist_ok=True)
        for f in Path(folder).glob("*.png"):
            shutil.copy(f, Path(keep, prefix + f.name))
    shutil.rmtree(folder)


def submodule(name):
    """The add-on's module `name` (e.g. "core", "blender.ui.panels"), whatever the package is called."""
    return importlib.import_module(f"{PACKAGE}.{name}")


def install_and_enable(zip_path):
    if not os.environ.get("BLENDER_USER_SCRIPTS"):
        sys.exit("BLENDER_USER_SCRIPTS must point to a scratch folder (ctest sets it)")
    result = bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    assert result == {"FINISHED"}, result
    module = addon_utils.enable("fracterra", default_set=True, handle_error=None)
    assert module is not None, "the add-on did not enable"
    return module


def find_enabled():
    """The enabled add-on whose module is fracterra or ends in .fracterra (an extension)."""
    names = [a.module for a in bpy.context.preferences.addons
             if a.module == "fracterra" or a.module.endswith(".fracterra")]
    assert len(names) == 1, f"expected one enabled fracterra add-on, found {names}"
    return importlib.import_module(names[0])


def run(test_module_globals):
    global PACKAGE
    options = args()
    module = find_enabled() if options.installed else install_and_enable(options.zip)
    PACKAGE = module.__name__
    print(f"testing the add-on {PACKAGE} in Blender {bpy.app.version_string}", flush=True)
    loader = unittest.TestLoader()
    loader.testNamePatterns = [p if "*" in p else f"*{p}*" for p in options.patterns or []] or None
    suite = unittest.TestSuite()
    for obj in list(test_module_globals.values()):
        if isinstance(obj, type) and issubclass(obj, unittest.TestCase):
            suite.addTests(loader.loadTestsFromTestCase(obj))
    result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
    sys.stdout.flush()
    # os._exit: Blender would otherwise swallow the code on its way out.
    os._exit(0 if result.wasSuccessful() else 1)
