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
    FT_FIELD(ft_terrain_params, levelling), FT_FIELD(ft_terrain_params, height_offset),
    FT_FIELD(ft_terrain_params, falloff), FT_FIELD(ft_terrain_params, falloff_width),
    FT_FIELD(ft_terrain_params, edge_level), FT_FIELD(ft_terrain_params, sea),
    FT_FIELD(ft_terrain_params, sea_level), FT_FIELD(ft_terrain_params, sea_fraction),
    FT_FIELD(ft_terrain_params, falloff_mask), FT_FIELD(ft_terrain_params, falloff_mask_width),
    FT_FIELD(ft_terrain_params, falloff_mask_height),
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
    FT_FIELD(ft_erosion_params, progress_user), FT_FIELD(ft_erosion_params, uplift_follows_terrain),
};
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
};

const std::vector<Field> kPovSceneFields = {
    FT_FIELD(ft_pov_scene_params, struct_size), FT_FIELD(ft_pov_scene_params, terrain),
    FT_FIELD(ft_pov_scene_params, world_size_x), FT_FIELD(ft_pov_scene_params, world_size_y),
    FT_FIELD(ft_pov_scene_params, vertical_scale), FT_FIELD(ft_pov_scene_params, has_sea),
    FT_FIELD(ft_pov_scene_params, sea_level), FT_FIELD(ft_pov_scene_params, lines),
    FT_FIELD(ft_pov_scene_params, line_set_count), FT_FIELD(ft_pov_scene_params, camera_azimuth_deg),
    FT_FIELD(ft_pov_scene_params, camera_elevation_deg), FT_FIELD(ft_pov_scene_params, camera_fov_deg),
    FT_FIELD(ft_pov_scene_params, camera_aspect), FT_FIELD(ft_pov_scene_params, camera_distance_scale),
    FT_FIELD(ft_pov_scene_params, sun_azimuth_deg), FT_FIELD(ft_pov_scene_params, sun_elevation_deg),
    FT_FIELD(ft_pov_scene_params, image_path), FT_FIELD(ft_pov_scene_params, camera_margin),
    FT_FIELD(ft_pov_scene_params, camera_center_v),
};
const std::vector<Field> kPovSweepFields = {
    FT_FIELD(ft_pov_sweep_params, struct_size), FT_FIELD(ft_pov_sweep_params, spline),
    FT_FIELD(ft_pov_sweep_params, segments_per_sweep), FT_FIELD(ft_pov_sweep_params, default_radius),
    FT_FIELD(ft_pov_sweep_params, radius_scale), FT_FIELD(ft_pov_sweep_params, tolerance),
};
const std::vector<Field> kHurstFields = {
    FT_FIELD(ft_hurst_params, struct_size), FT_FIELD(ft_hurst_params, method), FT_FIELD(ft_hurst_params, lag_min),
    FT_FIELD(ft_hurst_params, lag_max), FT_FIELD(ft_hurst_params, freq_min), FT_FIELD(ft_hurst_params, freq_max),
    FT_FIELD(ft_hurst_params, transects),
};
const std::vector<Field> kCloudsFields = {
    FT_FIELD(ft_clouds_params, struct_size), FT_FIELD(ft_clouds_params, threshold),
    FT_FIELD(ft_clouds_params, threshold_is_quantile), FT_FIELD(ft_clouds_params, bit_depth),
};
const std::vector<Field> kDemRefineFields = {
    FT_FIELD(ft_dem_refine_params, struct_size), FT_FIELD(ft_dem_refine_params, levels_added),
    FT_FIELD(ft_dem_refine_params, hurst), FT_FIELD(ft_dem_refine_params, sigma),
    FT_FIELD(ft_dem_refine_params, seed), FT_FIELD(ft_dem_refine_params, method),
    FT_FIELD(ft_dem_refine_params, window_x), FT_FIELD(ft_dem_refine_params, window_y),
    FT_FIELD(ft_dem_refine_params, window_side), FT_FIELD(ft_dem_refine_params, threads),
    FT_FIELD(ft_dem_refine_params, progress), FT_FIELD(ft_dem_refine_params, progress_user),
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
    {FT_PARAMS_HYDROLOGY, "ft_hydrology_params", sizeof(ft_hydrology_params), &kHydrologyFields,
     init_of<ft_hydrology_params, ft_hydrology_params_init>},
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
