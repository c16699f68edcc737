// The parameter tables (fracterra/params.h) against the structs they
// describe: every row where the compiler puts its field, nothing missing,
// and the behaviour the tables drive (defaults, ranges, older struct sizes).
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

struct Field {
  const char* name;
  size_t offset, size;
};
#define FT_FIELD(S, f) Field{#f, offsetof(S, f), sizeof(S::f)}

// The header's fields, written out independently of the table.
const std::vector<Field> kTerrainFields = {
    FT_FIELD(ft_terrain_params, struct_size), FT_FIELD(ft_terrain_params, method),
    FT_FIELD(ft_terrain_params, levels), FT_FIELD(ft_terrain_params, width),
    FT_FIELD(ft_terrain_params, height), FT_FIELD(ft_terrain_params, hurst),
    FT_FIELD(ft_terrain_params, sigma), FT_FIELD(ft_terrain_params, seed),
    FT_FIELD(ft_terrain_params, periodic), FT_FIELD(ft_terrain_params, threads),
    FT_FIELD(ft_terrain_params, reference), FT_FIELD(ft_terrain_params, reference_size),
    FT_FIELD(ft_terrain_params, reference_scale), FT_FIELD(ft_terrain_params, octaves),
    FT_FIELD(ft_terrain_params, lacunarity), FT_FIELD(ft_terrain_params, gain),
    FT_FIELD(ft_terrain_params, basis), FT_FIELD(ft_terrain_params, variant),
    FT_FIELD(ft_terrain_params, frequency), FT_FIELD(ft_terrain_params, offset),
    FT_FIELD(ft_terrain_params, octave_rotation), FT_FIELD(ft_terrain_params, warp),
    FT_FIELD(ft_terrain_params, progress), FT_FIELD(ft_terrain_params, progress_user),
    FT_FIELD(ft_terrain_params, world_size), FT_FIELD(ft_terrain_params, center_x),
    FT_FIELD(ft_terrain_params, center_y), FT_FIELD(ft_terrain_params, zoom),
    FT_FIELD(ft_terrain_params, iterations), FT_FIELD(ft_terrain_params, supersample),
};

const std::vector<Field> kProfileFields = {
    FT_FIELD(ft_profile_params, struct_size), FT_FIELD(ft_profile_params, levels),
    FT_FIELD(ft_profile_params, hurst), FT_FIELD(ft_profile_params, sigma), FT_FIELD(ft_profile_params, seed),
    FT_FIELD(ft_profile_params, reference), FT_FIELD(ft_profile_params, reference_size),
    FT_FIELD(ft_profile_params, reference_scale), FT_FIELD(ft_profile_params, progress),
    FT_FIELD(ft_profile_params, progress_user),
};
const std::vector<Field> kPolylineFields = {
    FT_FIELD(ft_polyline_params, struct_size), FT_FIELD(ft_polyline_params, method),
    FT_FIELD(ft_polyline_params, rng), FT_FIELD(ft_polyline_params, depth),
    FT_FIELD(ft_polyline_params, spread), FT_FIELD(ft_polyline_params, min_length),
    FT_FIELD(ft_polyline_params, seed), FT_FIELD(ft_polyline_params, base),
    FT_FIELD(ft_polyline_params, base_count), FT_FIELD(ft_polyline_params, plane_normal),
    FT_FIELD(ft_polyline_params, branch_prob), FT_FIELD(ft_polyline_params, branch_decay),
    FT_FIELD(ft_polyline_params, branch_generations), FT_FIELD(ft_polyline_params, ifs_preset),
    FT_FIELD(ft_polyline_params, radius), FT_FIELD(ft_polyline_params, hurst),
    FT_FIELD(ft_polyline_params, ifs_table), FT_FIELD(ft_polyline_params, ifs_maps),
    FT_FIELD(ft_polyline_params, threads), FT_FIELD(ft_polyline_params, ifs_points),
    FT_FIELD(ft_polyline_params, progress), FT_FIELD(ft_polyline_params, progress_user),
};
const std::vector<Field> kFractalizeFields = {
    FT_FIELD(ft_fractalize_params, struct_size), FT_FIELD(ft_fractalize_params, levels),
    FT_FIELD(ft_fractalize_params, hurst), FT_FIELD(ft_fractalize_params, sigma),
    FT_FIELD(ft_fractalize_params, seed), FT_FIELD(ft_fractalize_params, scheme),
    FT_FIELD(ft_fractalize_params, mode), FT_FIELD(ft_fractalize_params, fix_boundary),
    FT_FIELD(ft_fractalize_params, scale_by_edge_length), FT_FIELD(ft_fractalize_params, weights),
    FT_FIELD(ft_fractalize_params, threads), FT_FIELD(ft_fractalize_params, progress),
    FT_FIELD(ft_fractalize_params, progress_user),
};
const std::vector<Field> kErosionFields = {
    FT_FIELD(ft_erosion_params, struct_size), FT_FIELD(ft_erosion_params, fluvial_steps),
    FT_FIELD(ft_erosion_params, fluvial_dt), FT_FIELD(ft_erosion_params, erodibility),
    FT_FIELD(ft_erosion_params, area_exponent), FT_FIELD(ft_erosion_params, diffusion),
    FT_FIELD(ft_erosion_params, uplift), FT_FIELD(ft_erosion_params, hydraulic_iterations),
    FT_FIELD(ft_erosion_params, hydraulic_dt), FT_FIELD(ft_erosion_params, rain),
    FT_FIELD(ft_erosion_params, evaporation), FT_FIELD(ft_erosion_params, capacity),
    FT_FIELD(ft_erosion_params, dissolve), FT_FIELD(ft_erosion_params, deposit),
    FT_FIELD(ft_erosion_params, thermal_iterations), FT_FIELD(ft_erosion_params, talus_degrees),
    FT_FIELD(ft_erosion_params, thermal_rate), FT_FIELD(ft_erosion_params, periodic),
    FT_FIELD(ft_erosion_params, threads), FT_FIELD(ft_erosion_params, progress),
    FT_FIELD(ft_erosion_params, progress_user),
};

struct Kind {
  int32_t kind;
  const char* name;
  size_t size;
  const std::vector<Field>* fields;
};
const Kind kKinds[] = {
    {FT_PARAMS_TERRAIN, "ft_terrain_params", sizeof(ft_terrain_params), &kTerrainFields},
    {FT_PARAMS_PROFILE, "ft_profile_params", sizeof(ft_profile_params), &kProfileFields},
    {FT_PARAMS_POLYLINE, "ft_polyline_params", sizeof(ft_polyline_params), &kPolylineFields},
    {FT_PARAMS_FRACTALIZE, "ft_fractalize_params", sizeof(ft_fractalize_params), &kFractalizeFields},
    {FT_PARAMS_EROSION, "ft_erosion_params", sizeof(ft_erosion_params), &kErosionFields},
};

std::vector<const ft_param_info*> rows_of(int32_t kind) {
  int32_t n = 0;
  EXPECT_EQ(ft_params_describe(kind, nullptr, nullptr, &n), FT_OK);
  std::vector<const ft_param_info*> rows(size_t(n), nullptr);
  for (int32_t i = 0; i < n; ++i) EXPECT_EQ(ft_params_field(kind, i, &rows[size_t(i)]), FT_OK);
  return rows;
}

TEST(Params, EveryKindIsDescribed) {
  static_assert(sizeof(kKinds) / sizeof(kKinds[0]) == FT_PARAMS_KIND_COUNT, "a kind without a test");
  for (const Kind& k : kKinds) {
    const char* name = nullptr;
    uint32_t size = 0;
    ASSERT_EQ(ft_params_describe(k.kind, &name, &size, nullptr), FT_OK);
    EXPECT_STREQ(name, k.name);
    EXPECT_EQ(size, k.size);
  }
  EXPECT_EQ(ft_params_describe(FT_PARAMS_KIND_COUNT, nullptr, nullptr, nullptr), FT_ERR_INVALID_ARGUMENT);
  const ft_param_info* row = nullptr;
  EXPECT_EQ(ft_params_field(FT_PARAMS_TERRAIN, -1, &row), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(row, nullptr);
}

TEST(Params, EveryRowsOffsetAndSizeMatchTheStruct) {
  for (const Kind& k : kKinds) {
    const auto rows = rows_of(k.kind);
    ASSERT_EQ(rows.size(), k.fields->size()) << k.name << ": a field without a row, or a row without a field";
    for (size_t i = 0; i < rows.size(); ++i) {
      const Field& f = (*k.fields)[i];
      EXPECT_STREQ(rows[i]->name, f.name) << k.name << " row " << i;
      EXPECT_EQ(rows[i]->offset, f.offset) << k.name << "." << f.name;
      EXPECT_EQ(rows[i]->size, f.size) << k.name << "." << f.name;
      EXPECT_EQ(rows[i]->struct_size, sizeof(ft_param_info));
      EXPECT_EQ(rows[i]->enum_count > 0, rows[i]->type == FT_PARAM_ENUM) << f.name;
      EXPECT_TRUE(rows[i]->label && *rows[i]->label && rows[i]->doc && *rows[i]->doc) << f.name;
    }
  }
}

TEST(Params, InitWritesEveryRowsDefault) {
  ft_terrain_params p;
  std::memset(&p, 0xA5, sizeof p);
  ASSERT_EQ(ft_terrain_params_init(&p), FT_OK);
  for (const ft_param_info* row : rows_of(FT_PARAMS_TERRAIN)) {
    const char* at = reinterpret_cast<const char*>(&p) + row->offset;
    double v = 0;
    switch (row->type) {
      case FT_PARAM_DOUBLE: std::memcpy(&v, at, 8); break;
      case FT_PARAM_UINT64: { uint64_t u; std::memcpy(&u, at, 8); v = double(u); break; }
      case FT_PARAM_UINT32: { uint32_t u; std::memcpy(&u, at, 4); v = u; break; }
      case FT_PARAM_INT32: case FT_PARAM_BOOL: case FT_PARAM_ENUM: { int32_t u; std::memcpy(&u, at, 4); v = u; break; }
      default: { void* q; std::memcpy(&q, at, sizeof q); EXPECT_EQ(q, nullptr) << row->name; continue; }
    }
    EXPECT_EQ(v, row->default_value) << row->name;
  }
}

TEST(Params, AHardRangeIsCheckedForTheFieldsTheMethodUses) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = 3;
  p.octaves = 0;  // fbm only: midpoint ignores it
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  ft_heightfield_free(hf);
  p.method = FT_TERRAIN_FBM;
  p.width = p.height = 16;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("octaves must be in 1..30, got 0"), std::string::npos)
      << ft_last_error();
  p.octaves = 4;
  p.basis = 9;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("basis must be one of 0 (VALUE)"), std::string::npos)
      << ft_last_error();
}

TEST(Params, ASizeBetweenTwoVersionsIsRefusedNamingTheSizesAllowed) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = 3;
  p.struct_size = offsetof(ft_terrain_params, world_size) + 4;  // no version ever had this size
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  const std::string sizes = std::to_string(offsetof(ft_terrain_params, world_size)) + ", " +
                            std::to_string(offsetof(ft_terrain_params, center_x)) + ", " +
                            std::to_string(sizeof(ft_terrain_params));
  EXPECT_NE(std::string(ft_last_error()).find(sizes), std::string::npos) << ft_last_error();
}

}  // namespace
