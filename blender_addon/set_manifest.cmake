# SPDX-License-Identifier: GPL-3.0-or-later
# Writes into a staged Blender 4.2+ manifest the platforms the package carries
# a library for ("linux-x64", plus "windows-x64" when fracterra.dll is there)
# and, for the extension's source folder, the wheels that carry it.
# Run as: cmake -DMANIFEST=.../blender_manifest.toml -DPLATFORMS=linux-x64,windows-x64
#               [-DWHEELS=/path/a.whl,/path/b.whl] -P set_manifest.cmake
file(READ ${MANIFEST} text)
string(REPLACE "," "\", \"" list "${PLATFORMS}")
string(REGEX REPLACE "platforms = \\[[^]]*\\]" "platforms = [\"${list}\"]" text "${text}")
if(WHEELS)
  string(REPLACE "," ";" wheels "${WHEELS}")
  set(entries "")
  foreach(wheel ${wheels})
    get_filename_component(name ${wheel} NAME)
    string(APPEND entries "  \"./wheels/${name}\",\n")
  endforeach()
  # After `platforms`: a top-level key, before the first [table].
  string(REGEX REPLACE "(platforms = \\[[^]]*\\]\n)" "\\1wheels = [\n${entries}]\n" text "${text}")
endif()
file(WRITE ${MANIFEST} "${text}")
