# SPDX-License-Identifier: GPL-3.0-or-later
# Removes every __pycache__ folder under ROOT (the staged add-on, whose
# blender/ has a folder per role).
file(GLOB_RECURSE caches LIST_DIRECTORIES true ${ROOT}/*)
list(FILTER caches INCLUDE REGEX "/__pycache__$")
if(caches)
  file(REMOVE_RECURSE ${caches})
endif()
