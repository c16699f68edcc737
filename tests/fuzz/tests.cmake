# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzz harnesses (tests/fuzz/fuzz_<name>.cpp), built one or both of two ways:
#  - FT_FUZZ=ON (clang): libFuzzer programs fuzz_<name>, run by run_fuzzers.sh;
#  - otherwise, and in a build that is both FT_FUZZ and FT_SANITIZE (the CI's
#    one clang build, tests/sanitize.sh): fuzz_<name>_replay, the same harness
#    behind a small driver that replays tests/fuzz/corpus/<name>/ and
#    tests/fuzz/regressions/<name>/; ctest runs it (label "native", so the
#    sanitizer build runs it too). With both, each harness is compiled once
#    (an object library) and linked into both programs.
file(GLOB FT_FUZZ_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/fuzz_*.cpp)
set(FT_FUZZ_REPLAY OFF)
if(NOT FT_FUZZ OR FT_SANITIZE)
  set(FT_FUZZ_REPLAY ON)
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
  add_library(${name}_harness OBJECT ${src})
  target_link_libraries(${name}_harness PRIVATE ${lib})
  target_include_directories(${name}_harness PRIVATE ${CMAKE_CURRENT_LIST_DIR} ${PROJECT_SOURCE_DIR}/native/src)
  set(programs "")
  if(FT_FUZZ)
    add_executable(${name} $<TARGET_OBJECTS:${name}_harness>)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    list(APPEND programs ${name})
  endif()
  if(FT_FUZZ_REPLAY)
    add_executable(${name}_replay $<TARGET_OBJECTS:${name}_harness> $<TARGET_OBJECTS:fuzz_replay_main>)
    add_test(NAME fuzz_replay_${harness}
             COMMAND ${name}_replay ${CMAKE_CURRENT_LIST_DIR}/corpus/${harness}
                     ${CMAKE_CURRENT_LIST_DIR}/regressions/${harness})
    set_tests_properties(fuzz_replay_${harness} PROPERTIES LABELS "native;fuzz")
    list(APPEND programs ${name}_replay)
  endif()
  foreach(program ${programs})
    target_link_libraries(${program} PRIVATE ${lib})
  endforeach()
endforeach()
