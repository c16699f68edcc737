// SPDX-License-Identifier: GPL-3.0-or-later
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
// FT_FIELDS(S, a, b, ...): FT_FIELD(S, a), FT_FIELD(S, b), ... (a preprocessor
// loop: each FT_FIELDS_EXPAND pass lets the next name expand, 4^4 = 256 names).
#define FT_FIELDS(S, ...) __VA_OPT__(FT_FIELDS_EXPAND(FT_FIELDS_NEXT(S, __VA_ARGS__)))
#define FT_FIELDS_NEXT(S, f, ...) FT_FIELD(S, f) __VA_OPT__(, FT_FIELDS_AGAIN FT_FIELDS_PARENS(S, __VA_ARGS__))
#define FT_FIELDS_AGAIN() FT_FIELDS_NEXT
#define FT_FIELDS_PARENS ()
#define FT_FIELDS_EXPAND(...) FT_FIELDS_EXPAND3(FT_FIELDS_EXPAND3(FT_FIELDS_EXPAND3(FT_FIELDS_EXPAND3(__VA_ARGS__))))
#define FT_FIELDS_EXPAND3(...) FT_FIELDS_EXPAND2(FT_FIELDS_EXPAND2(FT_FIELDS_EXPAND2(FT_FIELDS_EXPAND2(__VA_ARGS__))))
#define FT_FIELDS_EXPAND2(...) FT_FIELDS_EXPAND1(FT_FIELDS_EXPAND1(FT_FIELDS_EXPAND1(FT_FIELDS_EXPAND1(__VA_ARGS__))))
#define FT_FIELDS_EXPAND1(...) __VA_ARGS__

// The header's fields, written out independently of the table.
const std::vector<Field> kTerrainFields = {
    FT_FIELDS(ft_terrain_params, struct_size, method, levels, width, height, hurst, sigma, seed, periodic, threads,
        reference, reference_size, reference_scale, octaves, lacunarity, gain, basis, variant, frequency, offset,
        octave_rotation, warp, progress, progress_user, world_size, center_x, center_y, zoom, iterations,
        supersample, levelling, height_offset, falloff, falloff_width, edge_level, sea, sea_level, sea_fraction,
        falloff_mask, falloff_mask_width, falloff_mask_height),
};

const std::vector<Field> kProfileFields = {
    FT_FIELDS(ft_profile_params, struct_size, levels, hurst, sigma, seed, reference, reference_size,
        reference_scale, progress, progress_user),
};
const std::vector<Field> kPolylineFields = {
    FT_FIELDS(ft_polyline_params, struct_size, method, rng, depth, spread, min_length, seed, base, base_count,
        plane_normal, branch_prob, branch_decay, branch_generations, ifs_preset, radius, hurst, ifs_table, ifs_maps,
        threads, ifs_points, progress, progress_user),
};
const std::vector<Field> kFractalizeFields = {
    FT_FIELDS(ft_fractalize_params, struct_size, levels, hurst, sigma, seed, scheme, mode, fix_boundary,
        scale_by_edge_length, weights, threads, progress, progress_user),
};
const std::vector<Field> kErosionFields = {
    FT_FIELDS(ft_erosion_params, struct_size, fluvial_steps, fluvial_dt, erodibility, area_exponent, diffusion,
        uplift, hydraulic_iterations, hydraulic_dt, rain, evaporation, capacity, dissolve, deposit,
        thermal_iterations, talus_degrees, thermal_rate, periodic, threads, progress, progress_user,
        uplift_follows_terrain, strength, duration, deposition, rainfall, erosion_mask, erosion_mask_width,
        erosion_mask_height, rain_map, rain_map_width, rain_map_height, sea, sea_level, sea_fraction, scree_years),
};
const std::vector<Field> kBuildFields = {
    FT_FIELDS(ft_build_params, struct_size, threads, terrain, erosion, erosion_preset, progress, progress_user,
              rivers),
};
const std::vector<Field> kSplatFields = {
    FT_FIELDS(ft_splat_params, struct_size, name, height_min, height_max, height_blend, slope_min, slope_max,
              slope_blend, deposit_min, deposit_blend, flow_min, flow_blend, weight, color)};
const std::vector<Field> kHydrologyFields = {
    FT_FIELD(ft_hydrology_params, struct_size),       FT_FIELD(ft_hydrology_params, min_area),
    FT_FIELD(ft_hydrology_params, sea),               FT_FIELD(ft_hydrology_params, sea_level),
    FT_FIELD(ft_hydrology_params, sea_fraction),      FT_FIELD(ft_hydrology_params, min_lake_area),
    FT_FIELD(ft_hydrology_params, rain),              FT_FIELD(ft_hydrology_params, width_coefficient),
    FT_FIELD(ft_hydrology_params, width_exponent),    FT_FIELD(ft_hydrology_params, depth_coefficient),
    FT_FIELD(ft_hydrology_params, depth_exponent),    FT_FIELD(ft_hydrology_params, smoothing),
    FT_FIELD(ft_hydrology_params, meander_depth),     FT_FIELD(ft_hydrology_params, meander_spread),
    FT_FIELD(ft_hydrology_params, seed),              FT_FIELD(ft_hydrology_params, tolerance),
    FT_FIELD(ft_hydrology_params, periodic),          FT_FIELD(ft_hydrology_params, threads),
    FT_FIELD(ft_hydrology_params, sinks),             FT_FIELD(ft_hydrology_params, sink_count),
    FT_FIELD(ft_hydrology_params, progress),          FT_FIELD(ft_hydrology_params, progress_user),
    FT_FIELD(ft_hydrology_params, min_depth),  // 2.27
};
const std::vector<Field> kPlanetFields = {
    FT_FIELDS(ft_planet_params, struct_size, method, radius, sigma, hurst, octaves, lacunarity, frequency, basis,
              variant, offset, seed, sea, sea_level, sea_fraction, threads, progress, progress_user)};

const std::vector<Field> kPovSceneFields = {
    FT_FIELDS(ft_pov_scene_params, struct_size, terrain, world_size_x, world_size_y, vertical_scale, has_sea,
        sea_level, lines, line_set_count, camera_azimuth_deg, camera_elevation_deg, camera_fov_deg, camera_aspect,
        camera_distance_scale, sun_azimuth_deg, sun_elevation_deg, image_path, camera_margin, camera_center_v,
        camera_given, camera_location, camera_direction, camera_right, camera_up, terrain_colors, has_scene_light,
        sky_color, sun_color, lights, light_count, line_materials, rivers, water_material, meshes, mesh_count),
};
const std::vector<Field> kPovSweepFields = {
    FT_FIELDS(ft_pov_sweep_params, struct_size, spline, segments_per_sweep, default_radius, radius_scale, tolerance),
};
const std::vector<Field> kHurstFields = {
    FT_FIELDS(ft_hurst_params, struct_size, method, lag_min, lag_max, freq_min, freq_max, transects),
};
const std::vector<Field> kCloudsFields = {
    FT_FIELDS(ft_clouds_params, struct_size, threshold, threshold_is_quantile, bit_depth),
};
const std::vector<Field> kDemRefineFields = {
    FT_FIELDS(ft_dem_refine_params, struct_size, levels_added, hurst, sigma, seed, method, window_x, window_y,
        window_side, threads, progress, progress_user),
};

// Each struct's _init as one signature (ft_dem_refine_params_init returns nothing).
using InitFn = ft_status (*)(void*);
template <class S, ft_status (*F)(S*)>
ft_status init_of(void* p) { return F(static_cast<S*>(p)); }
ft_status init_dem_refine(void* p) {
  ft_dem_refine_params_init(static_cast<ft_dem_refine_params*>(p));
  return FT_OK;
}

struct Kind {
  int32_t kind;
  const char* name;
  size_t size;
  const std::vector<Field>* fields;
  InitFn init;
};
const Kind kKinds[] = {
    {FT_PARAMS_TERRAIN, "ft_terrain_params", sizeof(ft_terrain_params), &kTerrainFields,
     init_of<ft_terrain_params, ft_terrain_params_init>},
    {FT_PARAMS_PROFILE, "ft_profile_params", sizeof(ft_profile_params), &kProfileFields,
     init_of<ft_profile_params, ft_profile_params_init>},
    {FT_PARAMS_POLYLINE, "ft_polyline_params", sizeof(ft_polyline_params), &kPolylineFields,
     init_of<ft_polyline_params, ft_polyline_params_init>},
    {FT_PARAMS_FRACTALIZE, "ft_fractalize_params", sizeof(ft_fractalize_params), &kFractalizeFields,
     init_of<ft_fractalize_params, ft_fractalize_params_init>},
    {FT_PARAMS_POV_SCENE, "ft_pov_scene_params", sizeof(ft_pov_scene_params), &kPovSceneFields,
     init_of<ft_pov_scene_params, ft_pov_scene_params_init>},
    {FT_PARAMS_POV_SWEEP, "ft_pov_sweep_params", sizeof(ft_pov_sweep_params), &kPovSweepFields,
     init_of<ft_pov_sweep_params, ft_pov_sweep_params_init>},
    {FT_PARAMS_HURST, "ft_hurst_params", sizeof(ft_hurst_params), &kHurstFields,
     init_of<ft_hurst_params, ft_hurst_params_init>},
    {FT_PARAMS_CLOUDS, "ft_clouds_params", sizeof(ft_clouds_params), &kCloudsFields,
     init_of<ft_clouds_params, ft_clouds_params_init>},
    {FT_PARAMS_DEM_REFINE, "ft_dem_refine_params", sizeof(ft_dem_refine_params), &kDemRefineFields,
     init_dem_refine},
    {FT_PARAMS_EROSION, "ft_erosion_params", sizeof(ft_erosion_params), &kErosionFields,
     init_of<ft_erosion_params, ft_erosion_params_init>},
    {FT_PARAMS_BUILD, "ft_build_params", sizeof(ft_build_params), &kBuildFields,
     init_of<ft_build_params, ft_build_params_init>},
    {FT_PARAMS_HYDROLOGY, "ft_hydrology_params", sizeof(ft_hydrology_params), &kHydrologyFields,
     init_of<ft_hydrology_params, ft_hydrology_params_init>},
    {FT_PARAMS_PLANET, "ft_planet_params", sizeof(ft_planet_params), &kPlanetFields,
     init_of<ft_planet_params, ft_planet_params_init>},
    {FT_PARAMS_SPLAT, "ft_splat_params", sizeof(ft_splat_params), &kSplatFields,
     init_of<ft_splat_params, ft_splat_params_init>},
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
  for (const Kind& k : kKinds) {
    std::vector<unsigned char> buf(k.size);
    std::memset(buf.data(), 0xA5, buf.size());
    ASSERT_EQ(k.init(buf.data()), FT_OK) << k.name;
    const unsigned char* p = buf.data();
    for (const ft_param_info* row : rows_of(k.kind)) {
      for (int e = 0; e < row->count; ++e) {
        const unsigned char* at = p + row->offset + size_t(e) * (row->size / size_t(row->count));
        double v = 0;
        switch (row->type) {
          case FT_PARAM_DOUBLE: std::memcpy(&v, at, 8); break;
          case FT_PARAM_FLOAT: { float f; std::memcpy(&f, at, 4); v = f; break; }
          case FT_PARAM_UINT64: { uint64_t u; std::memcpy(&u, at, 8); v = double(u); break; }
          case FT_PARAM_INT64: { int64_t u; std::memcpy(&u, at, 8); v = double(u); break; }
          case FT_PARAM_UINT32: { uint32_t u; std::memcpy(&u, at, 4); v = u; break; }
          case FT_PARAM_INT32: case FT_PARAM_BOOL: case FT_PARAM_ENUM: { int32_t u; std::memcpy(&u, at, 4); v = u; break; }
          default: { void* q; std::memcpy(&q, at, sizeof q); EXPECT_EQ(q, nullptr) << k.name << "." << row->name; continue; }
        }
        EXPECT_EQ(v, row->default_value) << k.name << "." << row->name;
      }
    }
  }
}

// The defaults the headers promise, written out independently of the tables:
// a row whose default drifts from its header's word fails here.
TEST(Params, TheNewTablesDefaultsAreTheHeadersWords) {
  ft_pov_scene_params s;
  ASSERT_EQ(ft_pov_scene_params_init(&s), FT_OK);
  EXPECT_EQ(s.struct_size, sizeof s);
  EXPECT_EQ(s.world_size_x, 1);
  EXPECT_EQ(s.world_size_y, 1);
  EXPECT_EQ(s.vertical_scale, 1);
  EXPECT_EQ(s.has_sea, 0);
  EXPECT_EQ(s.camera_azimuth_deg, 200);
  EXPECT_EQ(s.camera_elevation_deg, 0);  // auto
  EXPECT_EQ(s.camera_margin, 0.04);
  EXPECT_EQ(s.camera_center_v, 0.55);
  EXPECT_EQ(s.camera_fov_deg, 50);
  EXPECT_EQ(s.camera_aspect, 4.0 / 3.0);
  EXPECT_EQ(s.camera_distance_scale, 1);
  EXPECT_EQ(s.sun_azimuth_deg, 235);
  EXPECT_EQ(s.sun_elevation_deg, 35);
  EXPECT_EQ(s.image_path, nullptr);
  ft_pov_sweep_params w;
  ASSERT_EQ(ft_pov_sweep_params_init(&w), FT_OK);
  EXPECT_EQ(w.spline, FT_POV_SWEEP_LINEAR);
  EXPECT_EQ(w.segments_per_sweep, 32);
  EXPECT_EQ(w.default_radius, 0.01);
  EXPECT_EQ(w.radius_scale, 1);
  EXPECT_EQ(w.tolerance, 1e-3);
  ft_hurst_params h;
  ASSERT_EQ(ft_hurst_params_init(&h), FT_OK);
  EXPECT_EQ(h.method, FT_HURST_VARIOGRAM_ALIGNED);
  EXPECT_EQ(h.lag_min, 0);
  EXPECT_EQ(h.freq_max, 0);
  EXPECT_EQ(h.transects, 0);
  ft_clouds_params c;
  ASSERT_EQ(ft_clouds_params_init(&c), FT_OK);
  EXPECT_EQ(c.threshold, 0.5);
  EXPECT_EQ(c.threshold_is_quantile, 1);
  EXPECT_EQ(c.bit_depth, 8);
  ft_dem_refine_params r;
  ft_dem_refine_params_init(&r);
  EXPECT_EQ(r.levels_added, 2);
  EXPECT_EQ(r.hurst, -1);
  EXPECT_EQ(r.sigma, -1);
  EXPECT_EQ(r.seed, 1u);
  EXPECT_EQ(r.method, FT_TERRAIN_MIDPOINT);
  EXPECT_EQ(r.window_x, -1);
  EXPECT_EQ(r.window_y, -1);
  EXPECT_EQ(r.window_side, 0);
  EXPECT_EQ(r.threads, 0);
}

// The new tables' ranges reach the library's boundary: one field out of its
// row's range is refused, naming the field, before any work.
TEST(Params, TheNewTablesRangesAreChecked) {
  ft_heightfield* hf = nullptr;
  std::vector<float> z(16 * 16);
  for (size_t i = 0; i < z.size(); ++i) z[i] = float((i * 7919) % 31);
  ASSERT_EQ(ft_heightfield_create(16, 16, z.data(), &hf), FT_OK);
  auto refused = [](ft_status st, const char* words) {
    EXPECT_EQ(st, FT_ERR_INVALID_ARGUMENT) << words;
    EXPECT_NE(std::string(ft_last_error()).find(words), std::string::npos) << ft_last_error();
  };
  ft_hurst_params h;
  ft_hurst_params_init(&h);
  h.method = 6;
  ft_hurst_result res{};
  res.struct_size = sizeof res;
  refused(ft_hurst_heightfield(hf, &h, &res), "method must be one of");
  ft_hurst_params_init(&h);
  h.lag_max = -3;
  refused(ft_hurst_heightfield(hf, &h, &res), "lag_max must be a finite number >= 0, got -3");
  h.lag_max = 0;
  h.freq_max = -3;  // the aligned variogram reads no frequency: not checked
  EXPECT_EQ(ft_hurst_heightfield(hf, &h, &res), FT_OK) << ft_last_error();
  h.method = FT_HURST_SPECTRAL;
  refused(ft_hurst_heightfield(hf, &h, &res), "freq_max must be a finite number >= 0, got -3");

  ft_clouds_params c;
  ft_clouds_params_init(&c);
  c.bit_depth = 32;
  std::vector<uint16_t> grey(z.size());
  refused(ft_clouds(hf, &c, grey.data(), grey.size()), "bit_depth must be in 8..16, got 32");
  ft_clouds_params_init(&c);
  c.threshold = 1.5;  // a quantile above 1: the cross-field check
  refused(ft_clouds(hf, &c, grey.data(), grey.size()), "threshold (a quantile)");
  c.threshold_is_quantile = 0;  // a height of 1.5 is fine
  EXPECT_EQ(ft_clouds(hf, &c, grey.data(), grey.size()), FT_OK) << ft_last_error();

  ft_pov_scene_params s;
  ft_pov_scene_params_init(&s);
  s.terrain = hf;
  s.sun_elevation_deg = 0;
  refused(ft_pov_write_scene(&s, "/nonexistent-dir/x.pov"), "sun_elevation_deg must be in [1, 90], got 0");
  ft_pov_scene_params_init(&s);
  s.terrain = hf;
  s.world_size_x = 0;
  refused(ft_pov_write_scene(&s, "/nonexistent-dir/x.pov"), "world_size_x must be a finite number > 0, got 0");

  ft_pov_sweep_params w;
  ft_pov_sweep_params_init(&w);
  w.segments_per_sweep = 0;
  ft_polylines* lines = nullptr;
  const double xyz[] = {0, 0, 0, 1, 0, 0};
  const int64_t offsets[] = {0, 2};
  ASSERT_EQ(ft_polylines_create(xyz, nullptr, 2, offsets, 1, &lines), FT_OK) << ft_last_error();
  refused(ft_pov_write_sweeps(lines, &w, "/nonexistent-dir/x.inc", "Lines"), "segments_per_sweep must be in 1..");
  ft_pov_sweep_params_init(&w);
  w.spline = 2;
  refused(ft_pov_write_sweeps(lines, &w, "/nonexistent-dir/x.inc", "Lines"), "spline must be one of 0 (LINEAR)");
  ft_polylines_free(lines);

  ft_dem_refine_params r;
  ft_dem_refine_params_init(&r);
  r.levels_added = 13;
  ft_heightfield* out = nullptr;
  refused(ft_dem_refine(hf, &r, &out, nullptr), "levels_added must be in 1..12, got 13");
  ft_dem_refine_params_init(&r);
  r.method = FT_TERRAIN_FBM;
  refused(ft_dem_refine(hf, &r, &out, nullptr), "method must be one of 0 (MIDPOINT), 1 (ADDITIONS)");
  ft_dem_refine_params_init(&r);
  r.hurst = 0.995;
  refused(ft_dem_refine(hf, &r, &out, nullptr), "hurst must be a finite number <= 0.99, got 0.995");
  ft_dem_refine_params_init(&r);
  r.struct_size = 12;
  refused(ft_dem_refine(hf, &r, &out, nullptr), "ft_dem_refine_params.struct_size is 12");
  EXPECT_EQ(out, nullptr);
  ft_heightfield_free(hf);
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
                            std::to_string(offsetof(ft_terrain_params, levelling)) + ", " +
                            std::to_string(offsetof(ft_terrain_params, falloff_mask)) + ", " +
                            std::to_string(sizeof(ft_terrain_params));
  EXPECT_NE(std::string(ft_last_error()).find(sizes), std::string::npos) << ft_last_error();
}

}  // namespace
