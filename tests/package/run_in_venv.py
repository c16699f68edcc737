# SPDX-License-Identifier: GPL-3.0-or-later
"""Installs the wheel into a fresh venv and runs this folder's pytest suite
with that venv's Python, from a temporary folder, with no PYTHONPATH and no
FRACTERRA_LIBRARY: what is tested is what `pip install` put there.

    run_in_venv.py WHEEL VENV_DIR TEST_DIR
"""

import os
import shutil
import subprocess
import sys
import tempfile


def main(wheel, venv, tests):
    shutil.rmtree(venv, ignore_errors=True)
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], check=True)
    py = os.path.join(venv, "bin", "python")
    subprocess.run([py, "-m", "pip", "install", "-q", "--no-index", "--no-build-isolation", wheel], check=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "FRACTERRA_LIBRARY")}
    with tempfile.TemporaryDirectory(prefix="ft_package_") as work:
        return subprocess.run([py, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--rootdir", work, tests],
                              cwd=work, env=env).returncode


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
