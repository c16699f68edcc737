// SPDX-License-Identifier: GPL-3.0-or-later
#include "engines/engine_preset.hpp"

#include <cstdlib>

#include "core/error.hpp"

namespace ft::engines {
namespace {

// Unreal's recommended landscape sizes and their import layouts (Unreal
// Engine documentation, "Landscape Technical Guide": recommended sizes).
constexpr struct {
  int32_t side;
  UnrealLayout layout;
} kUnreal[] = {{505, {63, 2, 4}}, {1009, {63, 2, 8}}, {2017, {63, 2, 16}}, {4033, {63, 2, 32}}, {8129, {127, 2, 32}}};

constexpr int32_t kGodotWorld = 16384;

}  // namespace

Engine parse_engine(const std::string& name) {
  if (name == "unity") return Engine::unity;
  if (name == "unreal") return Engine::unreal;
  if (name == "godot") return Engine::godot;
  invalid("unknown engine '" + name + "' (known: unity, unreal, godot)");
}

const char* engine_name(Engine e) {
  switch (e) {
    case Engine::unity: return "unity";
    case Engine::unreal: return "unreal";
    default: return "godot";
  }
}

void check_region_size(int32_t r) {
  if (r < 64 || r > 2048 || (r & (r - 1)) != 0)
    invalid("the Terrain3D region size must be a power of two in 64..2048, got " + std::to_string(r));
}

std::vector<int32_t> engine_sides(Engine e, int32_t region_size) {
  std::vector<int32_t> sides;
  switch (e) {
    case Engine::unity:  // Unity's heightmap resolutions: 33 .. 4097
      for (int32_t n = 32; n <= 4096; n *= 2) sides.push_back(n + 1);
      break;
    case Engine::unreal:
      for (const auto& u : kUnreal) sides.push_back(u.side);
      break;
    case Engine::godot:
      check_region_size(region_size);
      for (int32_t n = region_size; n <= kGodotWorld; n += region_size) sides.push_back(n);
      break;
  }
  return sides;
}

int32_t engine_side(Engine e, int32_t n, int32_t region_size) {
  int32_t best = 0;
  for (int32_t s : engine_sides(e, region_size))
    if (best == 0 || std::abs(s - n) <= std::abs(best - n)) best = s;
  return best;
}

double unreal_z_scale(double height_range_m) {
  check_finite("height range", height_range_m);
  return height_range_m * 100.0 * 128.0 / 65535.0;
}

double unreal_location_z_cm(double min_m, double z_scale) { return 100.0 * min_m + 32768.0 / 128.0 * z_scale; }

UnrealLayout unreal_layout(int32_t side) {
  for (const auto& u : kUnreal)
    if (u.side == side) return u.layout;
  invalid("Unreal's recommended landscape sizes are 505, 1009, 2017, 4033 and 8129, got " + std::to_string(side));
}

uint32_t terrain3d_control(uint32_t base, uint32_t overlay, uint32_t blend) {
  return (base & 0x1Fu) << 27 | (overlay & 0x1Fu) << 22 | (blend & 0xFFu) << 14;
}

}  // namespace ft::engines
