# SPDX-License-Identifier: GPL-3.0-or-later
# Every command of the README and the user guides runs as written
# (run_doc_commands.py: examples run, synopses are skipped, the few left out
# say why in its NOT_RUN), with the built CLI first on PATH and the Python
# package staged from the source beside the built library. The examples are
# kept small enough for every test run (the script prints each one's CPU time:
# about 70 s of CPU in all); COST starts it early, so that it does not end alone.
find_program(FT_DOCS_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT FT_DOCS_PYTHON3)
  find_program(FT_DOCS_PYTHON3 NAMES python3 REQUIRED)
endif()
add_test(NAME doc_commands
  COMMAND ${FT_DOCS_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/run_doc_commands.py --cli $<TARGET_FILE:fracterra_cli>
          --library $<TARGET_FILE:fracterra> --timeout 120)
set_tests_properties(doc_commands PROPERTIES LABELS docs TIMEOUT 600 COST 30
  ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1;OMP_WAIT_POLICY=passive")
# Every relative link and image of the README and the guides names a file.
add_test(NAME doc_links COMMAND ${FT_DOCS_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/check_doc_links.py)
set_tests_properties(doc_links PROPERTIES LABELS docs TIMEOUT 60)
