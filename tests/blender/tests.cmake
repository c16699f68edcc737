# SPDX-License-Identifier: GPL-3.0-or-later
# The add-on in real Blender (blender -b --factory-startup): the built zip is
# installed into a scratch user scripts folder and every operator is run.
find_program(FT_BLENDER blender)
if(FT_BLENDER)
  set(FT_BLENDER_ZIP ${PROJECT_BINARY_DIR}/blender_addon/fracterra.zip)
  foreach(name addon missing_library params dem tiles erosion pov_export preview rivers river_render planet splat_material
               children without_gdal)
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_${name})
    add_test(NAME blender_${name}
      COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${scratch}
              ${FT_BLENDER} -b --factory-startup --python-exit-code 1
              --python ${CMAKE_CURRENT_LIST_DIR}/test_${name}.py -- --zip ${FT_BLENDER_ZIP})
    set_tests_properties(blender_${name} PROPERTIES LABELS blender TIMEOUT 120
      FIXTURES_REQUIRED blender_scratch)
  endforeach()
  # The installed add-on must use its bundled library, except in the test of a missing one.
  set_tests_properties(blender_addon blender_params blender_dem blender_tiles blender_erosion blender_pov_export
    blender_preview blender_rivers blender_river_render blender_planet blender_splat_material blender_children
    PROPERTIES ENVIRONMENT_MODIFICATION "FRACTERRA_LIBRARY=unset:")
  # COST: about 30 s in a CI run, so a clean clone's ctest starts it early.
  set_tests_properties(blender_pov_export PROPERTIES COST 12)
  # The Erode step is checked against the CLI, another front end of the library's pipeline.
  set_tests_properties(blender_erosion PROPERTIES ENVIRONMENT "FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>")
  # Rivers and Lakes too: the rivers are those `fracterra terrain --rivers` traces.
  set_tests_properties(blender_rivers PROPERTIES ENVIRONMENT "FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>")
  # The planet's sea height is checked against `fracterra planet --stats`.
  set_tests_properties(blender_planet PROPERTIES ENVIRONMENT "FRACTERRA_CLI=$<TARGET_FILE:fracterra_cli>")
  # A system without GDAL: FRACTERRA_GDAL names a file that does not exist, the only candidate then.
  set_tests_properties(blender_without_gdal PROPERTIES
    ENVIRONMENT "FRACTERRA_GDAL=${CMAKE_CURRENT_BINARY_DIR}/no-such-dir/libgdal.so.32"
    ENVIRONMENT_MODIFICATION "FRACTERRA_LIBRARY=unset:")
  set_tests_properties(blender_missing_library PROPERTIES
    ENVIRONMENT "FRACTERRA_LIBRARY=${CMAKE_CURRENT_BINARY_DIR}/no-such-dir/libfracterra.so")
  add_test(NAME blender_scratch_clean
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_addon
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_missing_library
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_params
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_dem
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_tiles
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_erosion
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_pov_export
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_preview
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_rivers
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_river_render
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_planet
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_splat_material
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_children
            ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_without_gdal)
  set_tests_properties(blender_scratch_clean PROPERTIES FIXTURES_SETUP blender_scratch LABELS blender)
endif()

# An example script run headless from the source tree with the built library,
# writing into example_<name>: the test blender_example_<name>.
function(ft_blender_example name script timeout)
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_example_${name})
  add_test(NAME blender_example_${name}
    COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${scratch} FRACTERRA_LIBRARY=$<TARGET_FILE:fracterra>
            ${FT_BLENDER} -b --factory-startup --python ${PROJECT_SOURCE_DIR}/examples/${script}
            -- --out ${CMAKE_CURRENT_BINARY_DIR}/example_${name} ${ARGN})
  set_tests_properties(blender_example_${name} PROPERTIES LABELS blender TIMEOUT ${timeout})
endfunction()
if(FT_BLENDER)
  # The demo scene (a tiny render keeps it to a few seconds).
  ft_blender_example(scene 20_blender_scene.py 120 --levels 6 --resolution 96x54 --samples 2)
  # The Mandelbrot example: terrain, level curves through the coastline operator, a tiny render.
  ft_blender_example(mandelbrot 21_blender_mandelbrot.py 120 --samples-x 65 --resolution 64x48 --samples 1)
  # The presets and the default beside A.N.T.'s default: every preset builds and renders (tiny).
  ft_blender_example(presets 22_blender_presets.py 180 --max-levels 5 --resolution 48x30 --samples 1)
  set_tests_properties(blender_example_presets PROPERTIES COST 20)
  # The planet example: Add Fractal Planet (level 5), sun, camera, a tiny render.
  ft_blender_example(planet 25_blender_planet.py 120 --level 5 --resolution 48x48 --samples 1)
endif()

# Undo needs a window (background Blender keeps no undo stack): run it under Xvfb.
find_program(FT_XVFB_RUN xvfb-run)
if(FT_BLENDER AND FT_XVFB_RUN)
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_undo)
  add_test(NAME blender_undo
    COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${scratch} --unset=FRACTERRA_LIBRARY
            ${FT_XVFB_RUN} -a -s "-screen 0 1024x768x24"
            ${FT_BLENDER} --factory-startup --python-exit-code 1
            --python ${CMAKE_CURRENT_LIST_DIR}/test_undo.py -- --zip ${FT_BLENDER_ZIP})
  # 300: the redo hand-over builds a 2049^2 terrain (about 20 s idle, 60 s at load 15).
  set_tests_properties(blender_undo PROPERTIES LABELS blender TIMEOUT 300 COST 20)
endif()

# The zip needs nothing beyond glibc, the C++ runtime and what it bundles.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME addon_zip_self_contained
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_zip.py ${FT_BLENDER_ADDON_ZIP})
  set_tests_properties(addon_zip_self_contained PROPERTIES LABELS blender TIMEOUT 60)
  # The notices list every bundled library of the zip and the wheels; the zip is within its size budget.
  add_test(NAME package_notices
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_notices.py ${FT_BLENDER_ADDON_ZIP}
            ${FT_PYTHON_WHEELS} ${FT_NATIVE_WHEELS})
  set_tests_properties(package_notices PROPERTIES LABELS blender TIMEOUT 60)
endif()

# The per-platform extensions, built, validated and (linux-x64) installed in
# Blender 4.3 inside a Debian trixie root built once into /var/cache/fracterra
# (about a minute on a fresh machine, then reused): no host Blender, libraries,
# GDAL or environment variables. Skipped (77) without root.
if(FT_EXTENSION_SOURCE)
  add_test(NAME blender4_extension
    COMMAND ${CMAKE_CURRENT_LIST_DIR}/blender4_extension.sh ${PROJECT_SOURCE_DIR} ${FT_EXTENSION_SOURCE}
            ${FT_EXTENSIONS_DIR})
  # (COST: it and blender_gui take over a minute each, so ctest starts them early.)
  set_tests_properties(blender4_extension PROPERTIES LABELS blender TIMEOUT 600 SKIP_RETURN_CODE 77 COST 75)
endif()

# The add-on in the real GUI under Xvfb, driven through the event loop with
# xdotool: menus, redo panels, sidebar panels, preferences, undo, redo; the
# screenshots land in blender_gui_shots/. Drawing code prints (not raises) its
# errors, so any traceback in the log fails the test. It takes about 100 s
# idle and took 191 s at load 7 (2026-11-27) against the 240 s it had: the
# timeout is for a hang, not for a busy machine.
find_program(FT_XDOTOOL xdotool)
if(FT_BLENDER AND FT_XVFB_RUN AND FT_XDOTOOL)
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/blender_user_scripts_gui)
  add_test(NAME blender_gui
    COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${scratch} --unset=FRACTERRA_LIBRARY
            ${FT_XVFB_RUN} -a -s "-screen 0 1280x800x24"
            ${FT_BLENDER} --factory-startup --window-geometry 0 0 1280 800
            --python ${CMAKE_CURRENT_LIST_DIR}/test_gui.py
            -- --zip ${FT_BLENDER_ZIP} --out ${CMAKE_CURRENT_BINARY_DIR}/blender_gui_shots)
  set_tests_properties(blender_gui PROPERTIES LABELS blender TIMEOUT 480 COST 65
    FAIL_REGULAR_EXPRESSION "Traceback|GUI test FAILED")
endif()
