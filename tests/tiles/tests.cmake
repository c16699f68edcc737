# SPDX-License-Identifier: GPL-3.0-or-later
# Tile sets on Dask (the Python package's fracterra.tiles, as pip installed it
# in a fresh venv: tests/package/run_in_venv.py): a LocalCluster of 2 real
# worker processes writes the same bytes as the one-process CLI, a worker
# killed mid-run changes nothing, a killed driver resumes, another terrain's
# folder is refused, an unreachable scheduler is named at once, and H from
# per-tile sums reduced on Dask equals the whole's. Small tiles: each test
# takes a few seconds (cluster start-up is most of it).
if(FT_PYTHON_WHEEL AND FT_VENV_PYTHON3)
  add_test(NAME tiles_dask
    COMMAND ${FT_VENV_PYTHON3} ${PROJECT_SOURCE_DIR}/tests/package/run_in_venv.py ${FT_PYTHON_WHEEL}
            ${CMAKE_CURRENT_BINARY_DIR}/tiles-venv ${CMAKE_CURRENT_LIST_DIR})
  set_tests_properties(tiles_dask PROPERTIES
    LABELS "python;dask"
    ENVIRONMENT "FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>;PYTHONDONTWRITEBYTECODE=1"
    TIMEOUT 300 COST 20)
endif()
