# SPDX-License-Identifier: GPL-3.0-or-later
# Cross-compiles for Windows x64 with Debian's mingw-w64, posix thread model
# (std::thread and OpenMP need winpthreads): scripts/build-windows.sh passes
# this file, and FT_MINGW_PREFIX, where scripts/mingw-deps.sh installed the
# static libpng and FFTW.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(FT_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${FT_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${FT_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${FT_MINGW_TRIPLE}-windres)
set(CMAKE_AR ${FT_MINGW_TRIPLE}-gcc-ar-posix CACHE FILEPATH "")
set(CMAKE_RANLIB ${FT_MINGW_TRIPLE}-gcc-ranlib-posix CACHE FILEPATH "")

# Headers and libraries come from the mingw sysroot (zlib: libz-mingw-w64-dev)
# and the dependency prefix only, never from the build machine's /usr.
set(FT_MINGW_PREFIX "$ENV{FT_MINGW_PREFIX}" CACHE PATH "static mingw dependencies (scripts/mingw-deps.sh)")
set(CMAKE_FIND_ROOT_PATH /usr/${FT_MINGW_TRIPLE} ${FT_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Static archives: fracterra.dll and fracterra.exe must need nothing beyond
# what Windows ships. zlib's sysroot has both libz.a and the import library
# libz.dll.a, which CMake's Windows platform file prefers; name the archive.
set(ZLIB_LIBRARY /usr/${FT_MINGW_TRIPLE}/lib/libz.a CACHE FILEPATH "static zlib (libz-mingw-w64-dev)")
set(ZLIB_INCLUDE_DIR /usr/${FT_MINGW_TRIPLE}/include CACHE PATH "")
# The same for libgomp, which FindOpenMP would take as libgomp.dll.a.
execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libgomp.a OUTPUT_VARIABLE FT_LIBGOMP
                OUTPUT_STRIP_TRAILING_WHITESPACE)
set(OpenMP_gomp_LIBRARY ${FT_LIBGOMP} CACHE FILEPATH "static libgomp (gcc-mingw-w64-x86-64-posix)")

# Programs built here run through Wine (ctest, add_test with a target).
find_program(FT_WINE NAMES wine64 wine PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(FT_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${FT_WINE})
endif()
