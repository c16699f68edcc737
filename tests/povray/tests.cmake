# SPDX-License-Identifier: GPL-3.0-or-later
# POV-Ray layer: real `povray` renders of the scenes fracterra writes, of the
# examples/1x_pov_*.pov scenes and of the povray_macros include files.
find_program(FT_POVRAY_EXE povray)
# A sanitizer build of a subset (tests/sanitize.sh, which runs the "native"
# label) leaves this program out unless named (45 s of CPU under ASan).
if(FT_SANITIZE_SUBSET AND NOT povray_render_test IN_LIST FT_SANITIZE_UNIT_TESTS)
elseif(FT_POVRAY_EXE)
  add_executable(povray_render_test ${CMAKE_CURRENT_LIST_DIR}/povray_render_test.cpp)
  target_link_libraries(povray_render_test PRIVATE fracterra_core GTest::gtest GTest::gtest_main)
  target_compile_definitions(povray_render_test PRIVATE
    FT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    FT_CLI_PATH="$<TARGET_FILE:fracterra_cli>")
  add_dependencies(povray_render_test fracterra_cli)
  gtest_discover_tests(povray_render_test DISCOVERY_TIMEOUT 60
                       PROPERTIES LABELS povray ENVIRONMENT FT_POVRAY=${FT_POVRAY_EXE})
else()
  message(WARNING "povray not found: the POV-Ray tests are skipped (apt-get install povray povray-includes)")
endif()

# examples/13_mandelbrot.sh end to end (terrain, curves, scene, a tiny render).
if(FT_POVRAY_EXE)
  add_test(NAME povray_example_mandelbrot
    COMMAND ${CMAKE_COMMAND} -E env FRACTERRA=$<TARGET_FILE:fracterra_cli> WIDTH=96 HEIGHT=72
            bash ${PROJECT_SOURCE_DIR}/examples/13_mandelbrot.sh ${CMAKE_CURRENT_BINARY_DIR}/example_mandelbrot)
  set_tests_properties(povray_example_mandelbrot PROPERTIES LABELS povray TIMEOUT 120)
endif()

# examples/14_eroded_terrain.sh end to end (terrain, erosion, maps, two tiny renders).
if(FT_POVRAY_EXE)
  add_test(NAME povray_example_eroded
    COMMAND ${CMAKE_COMMAND} -E env FRACTERRA=$<TARGET_FILE:fracterra_cli> SIZE=65 WIDTH=96 HEIGHT=72
            bash ${PROJECT_SOURCE_DIR}/examples/14_eroded_terrain.sh ${CMAKE_CURRENT_BINARY_DIR}/example_eroded)
  set_tests_properties(povray_example_eroded PROPERTIES LABELS povray TIMEOUT 120)
endif()
