# SPDX-License-Identifier: GPL-3.0-or-later
# Every source file names the project's licence (GPL-3.0-or-later, LICENSE)
# in an SPDX line (scripts/spdx_headers.py adds it); the self-test plants
# files without it in a scratch tree, so the check cannot pass by finding none.
find_program(FT_LICENCE_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT FT_LICENCE_PYTHON3)
  find_program(FT_LICENCE_PYTHON3 NAMES python3 REQUIRED)
endif()
add_test(NAME spdx_headers
  COMMAND ${FT_LICENCE_PYTHON3} ${PROJECT_SOURCE_DIR}/scripts/spdx_headers.py --check --root ${PROJECT_SOURCE_DIR})
add_test(NAME spdx_headers_self_test
  COMMAND ${FT_LICENCE_PYTHON3} ${PROJECT_SOURCE_DIR}/scripts/spdx_headers.py --self-test)
set_tests_properties(spdx_headers spdx_headers_self_test PROPERTIES LABELS licence TIMEOUT 60)
