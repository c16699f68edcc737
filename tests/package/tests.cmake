# SPDX-License-Identifier: GPL-3.0-or-later
# The Python package as a user installs it: the wheel pip-installed into a
# fresh venv (no index, no build isolation: this machine has no PyPI; the
# venv sees Debian's numpy and pytest), then pytest run from outside the
# source tree against what was installed.
find_program(FT_VENV_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(FT_PYTHON_WHEEL AND FT_VENV_PYTHON3)
  add_test(NAME python_package
    COMMAND ${FT_VENV_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/run_in_venv.py ${FT_PYTHON_WHEEL}
            ${CMAKE_CURRENT_BINARY_DIR}/package-venv ${CMAKE_CURRENT_LIST_DIR})
  set_tests_properties(python_package PROPERTIES
    LABELS python
    ENVIRONMENT "FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>;PYTHONDONTWRITEBYTECODE=1;FT_THREADS_IGNORE_LOAD=1"
    # COST: about 40 s in a CI run, so a clean clone's ctest (no cost data
    # yet) starts it among the first (docs/measurements/ci.md).
    TIMEOUT 300 COST 20)
endif()
