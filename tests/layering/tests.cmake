# SPDX-License-Identifier: GPL-3.0-or-later
# Includes point only downwards through the layers of native/ (the picture in
# docs/architecture.md, generated from the check's own table); the second test plants bad includes in a scratch tree and checks
# that each is reported, so the first cannot pass by reporting nothing.
find_program(FT_LAYERS_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT FT_LAYERS_PYTHON3)
  find_program(FT_LAYERS_PYTHON3 NAMES python3 REQUIRED)
endif()
add_test(NAME layering
  COMMAND ${FT_LAYERS_PYTHON3} ${PROJECT_SOURCE_DIR}/scripts/check_layers.py --root ${PROJECT_SOURCE_DIR})
add_test(NAME layering_self_test
  COMMAND ${FT_LAYERS_PYTHON3} ${PROJECT_SOURCE_DIR}/scripts/check_layers.py --self-test)
set_tests_properties(layering layering_self_test PROPERTIES LABELS layering TIMEOUT 60)
