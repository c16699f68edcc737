# SPDX-License-Identifier: GPL-3.0-or-later
# The river network's Horton ratio and Hack's h on real DEMs (Debian's
# matplotlib sample data): a real island in its sea must measure as the model's
# island in a sea is allowed to (docs/rivers.md, "Real terrain").
find_program(FT_PYTHON3_SYSTEM NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(FT_PYTHON3_SYSTEM)
  add_test(NAME real_dem_rivers
    COMMAND ${FT_PYTHON3_SYSTEM} ${CMAKE_CURRENT_LIST_DIR}/real_dem_rivers_test.py $<TARGET_FILE:fracterra_cli>)
  set_tests_properties(real_dem_rivers PROPERTIES LABELS native TIMEOUT 120 SKIP_RETURN_CODE 77)
endif()
