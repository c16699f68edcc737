# SPDX-License-Identifier: GPL-3.0-or-later
"""The windows-x64 extension installed by Blender 4.3's own installer on
Linux, the platform overridden (docs/windows.md): Blender refuses another
platform's package, so here Python's platform.system() and platform.machine()
say Windows / AMD64, in Blender and in the installer's subprocess
(bl_pkg's cli/blender_ext.py). Then Blender reads the manifest, checks the
package against "windows-x64", unpacks the add-on and installs its wheel into
the extensions' site-packages as on Windows. Checked: the add-on's files and
manifest, fracterra_native/lib/fracterra.dll where the binding looks for it,
and no Linux library. Loading the DLL needs Windows (check_wheel_dll.py loads
it under Wine instead).

    blender -b --factory-startup --python-exit-code 1 --python blender4_windows_install.py -- EXTENSION_ZIP

(in the trixie root: scripts/blender4-root.sh --run ROOT ... -- sh -c "blender ...").
Not in ctest yet: as of 2026-12-02 Blender installs and enables the extension
(the manifest's [build.generated] says windows-x64 and its wheel), but its
wheel sync leaves the win_amd64 wheel packed in the add-on's wheels/ folder:
the last check (the DLL in the extensions' site-packages) fails. Whether
Blender's wheel manager reads the platform elsewhere than platform.system()
is still to be found (docs/windows.md).
"""

import os
import platform
import sys


def pretend_windows(module):
    module.system = lambda: "Windows"
    module.machine = lambda: "AMD64"


pretend_windows(platform)

import bpy  # noqa: E402  (after the override: nothing may read the platform first)
import bl_pkg.bl_extension_utils as ext_utils  # noqa: E402

_command = ext_utils.blender_ext_cmd


def blender_ext_cmd_on_windows(python_args):
    """The installer's command, its Python told the same platform first."""
    cmd = _command(python_args)
    script = cmd[-1]
    code = ("import platform, runpy, sys; platform.system = lambda: 'Windows'; "
            "platform.machine = lambda: 'AMD64'; "
            f"sys.argv[0] = {script!r}; runpy.run_path({script!r}, run_name='__main__')")
    return (*cmd[:-1], "-c", code)


ext_utils.blender_ext_cmd = blender_ext_cmd_on_windows


def fail(message):
    print(f"FAIL: {message}")
    sys.stdout.flush()
    sys.exit(1)


def main():
    zip_path = sys.argv[sys.argv.index("--") + 1]
    print("platform as Blender's installer sees it:", ext_utils.platform_from_this_system())
    result = bpy.ops.extensions.package_install_files(filepath=zip_path, repo="user_default",
                                                      enable_on_install=True)
    if result != {"FINISHED"}:
        fail(f"package_install_files returned {result}")
    import addon_utils  # pylint: disable=import-outside-toplevel
    enabled = [name for name in bpy.context.preferences.addons.keys() if name.endswith(".fracterra")]
    print("enabled:", enabled)
    # Blender installs an enabled extension's wheels when it refreshes the extensions.
    addon_utils.extensions_refresh(ensure_wheels=True)
    repo = bpy.utils.user_resource("EXTENSIONS", path="user_default")
    addon = os.path.join(repo, "fracterra")
    manifest = os.path.join(addon, "blender_manifest.toml")
    if not os.path.isfile(manifest):
        fail(f"{manifest} was not installed: {os.listdir(repo) if os.path.isdir(repo) else 'no repository'}")
    text = open(manifest, encoding="utf-8").read()
    # (`extension build --split-platforms` keeps the source's list and adds its platform.)
    generated = text.split("[build.generated]", 1)[-1]
    if 'platforms = ["windows-x64"]' not in generated or "win_amd64.whl" not in generated:
        fail(f"the installed manifest's [build.generated] does not say windows-x64 and its wheel:\n{text}")
    if not os.path.isfile(os.path.join(addon, "core", "binding.py")):
        fail("the add-on's core/binding.py is missing")
    site = os.path.join(bpy.utils.user_resource("EXTENSIONS"), ".local", "lib",
                        f"python{sys.version_info.major}.{sys.version_info.minor}", "site-packages")
    dll = os.path.join(site, "fracterra_native", "lib", "fracterra.dll")
    if not os.path.isfile(dll):
        found = [os.path.join(d, f) for d, _, files in os.walk(bpy.utils.user_resource("EXTENSIONS")) for f in files
                 if f.endswith((".dll", ".so", ".whl"))]
        fail(f"Blender did not install the wheel's DLL at {dll}; found {found}")
    linux = [os.path.join(d, f) for d, _, files in os.walk(bpy.utils.user_resource("EXTENSIONS")) for f in files
             if ".so" in f]
    if linux:
        fail(f"the Windows extension brought Linux libraries: {linux}")
    with open(dll, "rb") as f:
        if f.read(2) != b"MZ":
            fail(f"{dll} is not a Windows DLL")
    print(f"OK: Blender {bpy.app.version_string} installed the windows-x64 extension: {addon}, wheel DLL {dll} "
          f"({os.path.getsize(dll)} bytes)")


main()
