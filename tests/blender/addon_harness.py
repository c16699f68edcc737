"""Shared set-up of the Blender tests: install the built add-on zip into the
temporary user scripts folder (BLENDER_USER_SCRIPTS, set by ctest), enable it,
and run a unittest module; the exit code tells ctest the result.

Run as: blender -b --factory-startup --python-exit-code 1 --python <test.py> -- --zip fracterra.zip
"""

import argparse
import os
import sys
import unittest

import addon_utils
import bpy


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser()
    parser.add_argument("--zip", required=True, help="the add-on zip built by CMake")
    return parser.parse_args(argv)


def install_and_enable(zip_path):
    if not os.environ.get("BLENDER_USER_SCRIPTS"):
        sys.exit("BLENDER_USER_SCRIPTS must point to a scratch folder (ctest sets it)")
    result = bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    assert result == {"FINISHED"}, result
    module = addon_utils.enable("fracterra", default_set=True, handle_error=None)
    assert module is not None, "the add-on did not enable"
    return module


def run(test_module_globals):
    install_and_enable(args().zip)
    loader = unittest.TestLoader()
    suite = unittest.TestSuite()
    for obj in list(test_module_globals.values()):
        if isinstance(obj, type) and issubclass(obj, unittest.TestCase):
            suite.addTests(loader.loadTestsFromTestCase(obj))
    result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
    sys.stdout.flush()
    # os._exit: Blender would otherwise swallow the code on its way out.
    os._exit(0 if result.wasSuccessful() else 1)
