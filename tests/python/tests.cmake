# SPDX-License-Identifier: GPL-3.0-or-later
# pytest suite of the add-on's ctypes binding (blender_addon/fracterra/core),
# run outside Blender against the freshly built libfracterra.so.
find_program(FT_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT FT_PYTHON3)
  find_program(FT_PYTHON3 NAMES python3)
endif()
add_test(NAME python_binding
  COMMAND ${FT_PYTHON3} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_LIST_DIR}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(python_binding PROPERTIES
  LABELS python
  ENVIRONMENT "FRACTERRA_LIBRARY=$<TARGET_FILE:fracterra>;FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>;PYTHONDONTWRITEBYTECODE=1;FT_THREADS_IGNORE_LOAD=1"
  TIMEOUT 240 COST 15)
