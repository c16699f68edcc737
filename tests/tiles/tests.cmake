# Tile sets on Dask (blender_addon/fracterra/core/tiles.py): a LocalCluster of
# 2 real worker processes writes the same bytes as the one-process CLI, a
# worker killed mid-run changes nothing, a killed driver resumes, another
# terrain's folder is refused, an unreachable scheduler is named at once, and
# H from per-tile sums reduced on Dask equals the whole's. Small tiles: each
# test takes a few seconds (cluster start-up is most of it).
add_test(NAME tiles_dask
  COMMAND ${FT_PYTHON3} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_LIST_DIR}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(tiles_dask PROPERTIES
  LABELS "python;dask"
  ENVIRONMENT "FRACTERRA_LIBRARY=$<TARGET_FILE:fracterra>;FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>;PYTHONDONTWRITEBYTECODE=1"
  TIMEOUT 300 COST 15)
