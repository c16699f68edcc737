// SPDX-License-Identifier: GPL-3.0-or-later
// What each game engine's terrain importer expects: side lengths, file
// format and the numbers to type into its import dialog (docs/engines.md).
//   Unity:  RAW16 little-endian ("byte order Windows"), square, 2^n + 1 samples.
//   Unreal: 16-bit PNG, square, one of the recommended landscape sizes
//           (505, 1009, 2017, 4033, 8129), with the Z scale for the importer.
//   Godot (Terrain3D): float EXR heights in world units and a control map
//           (texture ids and blend, Terrain3D's bit layout) at a multiple of
//           its region size.
// World units are taken as metres (Unity and Godot count in metres, Unreal
// in centimetres).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ft::engines {

enum class Engine { unity, unreal, godot };

Engine parse_engine(const std::string& name);  // "unity", "unreal", "godot"
const char* engine_name(Engine e);

// Terrain3D's region sizes are powers of two in this range; its default is 256.
inline constexpr int32_t kGodotDefaultRegion = 256;
void check_region_size(int32_t region_size);

// The side lengths the engine takes, smallest first (Godot: multiples of the
// region size up to 16384, Terrain3D's world).
std::vector<int32_t> engine_sides(Engine e, int32_t region_size = kGodotDefaultRegion);
// The one of them nearest to `n` samples (a tie goes to the larger).
int32_t engine_side(Engine e, int32_t n, int32_t region_size = kGodotDefaultRegion);

// Unreal maps a 16-bit sample v to z = (v - 32768) / 128 x ScaleZ centimetres
// (the landscape's Z scale, 100 by default: a 512 m range). The Z scale that
// spans `height_range_m` metres with the samples 0..65535:
//   ScaleZ = height_range_m x 100 cm/m x 128 / 65535.
double unreal_z_scale(double height_range_m);
// The landscape actor's Location Z (cm) that puts sample 0 at `min_m` metres:
// 100 min_m + 32768 / 128 x ScaleZ.
double unreal_location_z_cm(double min_m, double z_scale);

// Unreal's import dialog for a recommended size: quads per section, sections
// per component (per side) and components (per side), so that
// side - 1 = quads x sections x components.
struct UnrealLayout {
  int32_t quads_per_section = 0, sections_per_component = 0, components = 0;
};
UnrealLayout unreal_layout(int32_t side);

// Terrain3D's control map sample (a uint32 kept in a float's bits): base
// texture id in bits 27-31, overlay id in 22-26, blend in 14-21 (0: base
// only, 255: overlay only); the autoshader, hole and navigation bits stay 0.
uint32_t terrain3d_control(uint32_t base, uint32_t overlay, uint32_t blend);

}  // namespace ft::engines
