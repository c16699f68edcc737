# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzz harnesses (tests/fuzz/fuzz_<name>.cpp), built one of two ways:
#  - FT_FUZZ=ON (clang): libFuzzer programs fuzz_<name>, run by run_fuzzers.sh;
#  - otherwise: fuzz_<name>_replay, the same harness behind a small driver that
#    replays tests/fuzz/corpus/<name>/ and tests/fuzz/regressions/<name>/;
#    ctest runs it (label "native", so the sanitizer build runs it too).
file(GLOB FT_FUZZ_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/fuzz_*.cpp)
if(NOT FT_FUZZ)
  # The replay driver, compiled once for all the harnesses.
  add_library(fuzz_replay_main OBJECT ${CMAKE_CURRENT_LIST_DIR}/regression_main.cpp)
endif()
foreach(src ${FT_FUZZ_SOURCES})
  get_filename_component(name ${src} NAME_WE)
  string(REGEX REPLACE "^fuzz_" "" harness ${name})
  # The C ABI harness links the shared library, as ctypes does.
  if(harness MATCHES "^capi")
    set(lib fracterra)
  else()
    set(lib fracterra_core)
  endif()
  if(FT_FUZZ)
    add_executable(${name} ${src})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  else()
    set(name ${name}_replay)
    add_executable(${name} ${src} $<TARGET_OBJECTS:fuzz_replay_main>)
    add_test(NAME fuzz_replay_${harness}
             COMMAND ${name} ${CMAKE_CURRENT_LIST_DIR}/corpus/${harness}
                     ${CMAKE_CURRENT_LIST_DIR}/regressions/${harness})
    set_tests_properties(fuzz_replay_${harness} PROPERTIES LABELS "native;fuzz")
  endif()
  target_link_libraries(${name} PRIVATE ${lib})
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_LIST_DIR} ${PROJECT_SOURCE_DIR}/native/src)
endforeach()
