# SPDX-License-Identifier: GPL-3.0-or-later
# Tests on a real DEM (tests/raster/dem_test.cpp): the fixture fetches it
# from a Debian package once per build tree (fetch_dem.sh).
set(FT_DEM_DIR ${CMAKE_BINARY_DIR}/real-dem)
add_test(NAME fetch_real_dem COMMAND ${CMAKE_CURRENT_LIST_DIR}/fetch_dem.sh ${FT_DEM_DIR})
set_tests_properties(fetch_real_dem PROPERTIES FIXTURES_SETUP real_dem LABELS native TIMEOUT 300)

add_executable(dem_test ${CMAKE_CURRENT_LIST_DIR}/dem_test.cpp)
target_link_libraries(dem_test PRIVATE fracterra_core GTest::gtest GTest::gtest_main)
target_compile_definitions(dem_test PRIVATE FT_CLI_PATH="$<TARGET_FILE:fracterra_cli>")
add_dependencies(dem_test fracterra_cli)
gtest_discover_tests(dem_test DISCOVERY_TIMEOUT 60
  PROPERTIES LABELS native FIXTURES_REQUIRED real_dem ENVIRONMENT "FT_REAL_DEM=${FT_DEM_DIR}/elev.tif")

# A system without GDAL (the library opens the system's at run time): the CLI
# refuses GeoTIFF with what to install, and PNG, OpenEXR and RAW16 work.
find_package(Python3 COMPONENTS Interpreter)
if(FT_WITH_GDAL AND Python3_Interpreter_FOUND)
  add_test(NAME cli_without_gdal
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_without_gdal.py $<TARGET_FILE:fracterra_cli>
            ${CMAKE_CURRENT_BINARY_DIR}/without_gdal)
  set_tests_properties(cli_without_gdal PROPERTIES LABELS native TIMEOUT 60)
endif()
