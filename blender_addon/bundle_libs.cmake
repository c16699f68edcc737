# SPDX-License-Identifier: GPL-3.0-or-later
# Copies into DEST the shared libraries that LIBRARY (libfracterra.so) needs
# and an artist's machine may lack, each as a real file under the name the
# loader asks for (zip archives keep no symlinks). Left out: glibc, and the
# C++ runtime that the bundled OpenSubdiv needs (Blender itself is C++; our
# own code links libstdc++ statically).
# RECORD (optional) gets one line per library: its name and the file it was
# copied from, for THIRD_PARTY_NOTICES (scripts/third_party_notices.py).
# Run as: cmake -DLIBRARY=... -DDEST=... [-DRECORD=...] -P bundle_libs.cmake
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES ${LIBRARY}
  RESOLVED_DEPENDENCIES_VAR resolved
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  POST_EXCLUDE_REGEXES
    "/(ld-linux-x86-64|libc|libm|libdl|libpthread|librt|libmvec)\\.so"
    "/(libstdc\\+\\+|libgcc_s)\\.so")
if(unresolved)
  message(FATAL_ERROR "bundle_libs: cannot find ${unresolved} needed by ${LIBRARY}")
endif()
file(MAKE_DIRECTORY ${DEST})
set(record "")
foreach(lib ${resolved})
  get_filename_component(name ${lib} NAME)
  get_filename_component(real ${lib} REALPATH)
  file(COPY_FILE ${real} ${DEST}/${name} ONLY_IF_DIFFERENT)
  string(APPEND record "${name} ${lib}\n")
  message(STATUS "bundled ${name}")
endforeach()
if(RECORD)
  file(WRITE ${RECORD} "${record}")
endif()
