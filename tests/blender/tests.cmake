# The add-on in real Blender (blender -b --factory-startup): the built zip is
# installed into a scratch user scripts folder and every operator is run.
find_program(FT_BLENDER blender)
if(FT_BLENDER)
  set(FT_BLENDER_ZIP ${PROJECT_BINARY_DIR}/blender_addon/fracterra.zip)
  foreach(name addon missing_library)
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_${name})
    add_test(NAME blender_${name}
      COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${scratch}
              ${FT_BLENDER} -b --factory-startup --python-exit-code 1
              --python ${CMAKE_CURRENT_LIST_DIR}/test_${name}.py -- --zip ${FT_BLENDER_ZIP})
    set_tests_properties(blender_${name} PROPERTIES LABELS blender TIMEOUT 120
      FIXTURES_REQUIRED blender_scratch)
  endforeach()
  # The installed add-on must use its bundled library, except in the test of a missing one.
  set_tests_properties(blender_addon PROPERTIES ENVIRONMENT_MODIFICATION "FRACTERRA_LIBRARY=unset:")
  set_tests_properties(blender_missing_library PROPERTIES
    ENVIRONMENT "FRACTERRA_LIBRARY=${CMAKE_CURRENT_BINARY_DIR}/no-such-dir/libfracterra.so")
  add_test(NAME blender_scratch_clean
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_addon
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_missing_library)
  set_tests_properties(blender_scratch_clean PROPERTIES FIXTURES_SETUP blender_scratch LABELS blender)
endif()
