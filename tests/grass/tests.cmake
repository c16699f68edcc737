# SPDX-License-Identifier: GPL-3.0-or-later
# fracterra's drainage map against GRASS GIS (Debian grass-core): r.terraflow's
# multiple-flow accumulation on the same fixed terrain. Skipped (77) when
# GRASS is not installed.
find_program(FT_PYTHON3_SYSTEM NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(FT_PYTHON3_SYSTEM)
  add_test(NAME grass_drainage
    COMMAND ${FT_PYTHON3_SYSTEM} ${CMAKE_CURRENT_LIST_DIR}/grass_drainage.py $<TARGET_FILE:fracterra_cli>)
  set_tests_properties(grass_drainage PROPERTIES LABELS native TIMEOUT 120 SKIP_RETURN_CODE 77 COST 20)
endif()
# Horton's ratios of the river network against r.stream.extract's (issue 40).
if(FT_PYTHON3_SYSTEM)
  add_test(NAME grass_stream_orders
    COMMAND ${FT_PYTHON3_SYSTEM} ${CMAKE_CURRENT_LIST_DIR}/grass_stream_orders_test.py $<TARGET_FILE:fracterra_cli>)
  set_tests_properties(grass_stream_orders PROPERTIES LABELS native TIMEOUT 120 SKIP_RETURN_CODE 77 COST 10)
endif()
