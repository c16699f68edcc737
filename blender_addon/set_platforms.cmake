# Writes the platforms the zip carries a library for into the staged Blender
# 4.2+ manifest: "linux-x64", plus "windows-x64" when fracterra.dll is bundled.
# Run as: cmake -DMANIFEST=.../blender_manifest.toml -DPLATFORMS=linux-x64,windows-x64 -P set_platforms.cmake
file(READ ${MANIFEST} text)
string(REPLACE "," "\", \"" list "${PLATFORMS}")
string(REGEX REPLACE "platforms = \\[[^]]*\\]" "platforms = [\"${list}\"]" text "${text}")
file(WRITE ${MANIFEST} "${text}")
