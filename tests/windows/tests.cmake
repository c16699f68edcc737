# SPDX-License-Identifier: GPL-3.0-or-later
# The Windows build under Wine, from the Linux build's ctest (so `bash
# tests/run.sh`, which builds it first with scripts/build-windows.sh, runs
# them). Each test prints "SKIP: <why>" and is skipped (exit 77) where the
# Windows build, Wine or mingw's objdump is missing. docs/windows.md.
set(FT_WINDOWS_BIN "${PROJECT_SOURCE_DIR}/build-windows/bin" CACHE PATH
    "bin/ of the Windows build (scripts/build-windows.sh) whose programs the windows_* tests run under Wine")
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(FT_WINDOWS_EXE ${FT_WINDOWS_BIN}/fracterra.exe)

# The C ABI GoogleTest suites, cross-compiled and linked against fracterra.dll.
add_test(NAME windows_capi_suites_under_wine
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/wine_run.sh ${FT_WINDOWS_BIN}/windows_capitests.exe --gtest_brief=1)
# Only Windows system DLLs imported; only ft_* exported.
add_test(NAME windows_dll_imports_and_exports
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_dll.py
          ${FT_WINDOWS_BIN}/fracterra.dll ${FT_WINDOWS_EXE} ${FT_WINDOWS_BIN}/windows_capitests.exe)
foreach(case same_bits unicode_path refusals)
  add_test(NAME windows_cli_${case}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_windows_cli.py ${case}
            ${FT_WINDOWS_EXE} $<TARGET_FILE:fracterra_cli>)
endforeach()
set_tests_properties(windows_capi_suites_under_wine windows_dll_imports_and_exports windows_cli_same_bits
                     windows_cli_unicode_path windows_cli_refusals
  PROPERTIES LABELS windows SKIP_RETURN_CODE 77 ENVIRONMENT "${FT_TEST_ENV}"
             ENVIRONMENT_MODIFICATION "${FT_TEST_OMP}")
# The two longest (30 s and 11 s, idle) start early: numbered last, they
# otherwise ran last, one core idle beside them.
set_tests_properties(windows_cli_same_bits PROPERTIES COST 30)
set_tests_properties(windows_dll_imports_and_exports PROPERTIES COST 10)
set_tests_properties(windows_cli_unicode_path PROPERTIES COST 15)
