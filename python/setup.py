# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds the fracterra wheel from the staged package (python/CMakeLists.txt
stages it: this package's files, the add-on's bpy-free core/, lib/ with
libfracterra and its bundled libraries, THIRD_PARTY_NOTICES). The library is loaded by ctypes, so
the wheel does not depend on the CPython ABI: one py3-none-<platform> wheel
serves every Python 3. Run by CMake as
    python3 setup.py -q bdist_wheel --python-tag py3 --plat-name linux_x86_64 -d OUT
with Debian's setuptools and wheel (the build machine has no PyPI)."""

import os

from setuptools import setup

setup(
    name="fracterra",
    version=os.environ["FT_VERSION"],
    description="Fractal terrains, erosion and their measures (numpy API over libfracterra)",
    long_description=open("README.md", encoding="utf-8").read(),
    long_description_content_type="text/markdown",
    # The project's licence (LICENSE at the repository's root, staged beside
    # this file): the wheel's METADATA names it and its dist-info carries it.
    license="GPL-3.0-or-later",
    license_files=["LICENSE"],
    classifiers=["License :: OSI Approved :: GNU General Public License v3 or later (GPLv3+)"],
    python_requires=">=3.8",
    install_requires=["numpy"],
    packages=["fracterra", "fracterra.core"],
    package_data={"fracterra": ["lib/*", "THIRD_PARTY_NOTICES"], "fracterra.core": ["params.json"]},
    zip_safe=False,
)
