# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds fracterra_native, the wheel that carries the add-on's native library
to Blender 4.2+ (blender_manifest.toml's `wheels`): fracterra_native/lib/
holds libfracterra.so with the libraries it bundles (py3-none-linux_x86_64)
or fracterra.dll (py3-none-win_amd64), and THIRD_PARTY_NOTICES. It holds no
Python code beyond the library's path: the add-on loads it with ctypes
(core/binding.py), so it does not depend on the CPython ABI: --plat-name
alone tags it py3-none-<platform>. Staged and run by blender_addon/CMakeLists.txt as
    python3 setup.py -q bdist_wheel --python-tag py3 --plat-name PLATFORM -d OUT
"""

import os

from setuptools import setup

setup(
    name="fracterra_native",
    version=os.environ["FT_VERSION"],
    description="The native library of the fracterra Blender add-on (loaded by ctypes)",
    license="GPL-3.0-or-later",
    license_files=["LICENSE"],  # staged beside this file
    classifiers=["License :: OSI Approved :: GNU General Public License v3 or later (GPLv3+)"],
    python_requires=">=3.8",
    packages=["fracterra_native"],
    package_data={"fracterra_native": ["lib/*", "THIRD_PARTY_NOTICES"]},
    zip_safe=False,
)
