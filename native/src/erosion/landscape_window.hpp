// SPDX-License-Identifier: GPL-3.0-or-later
// The landscape model's coarse-to-fine path, by windows: the model's run on
// its own grid (global, but small: kModelCells across) from a subgrid of the
// terrain, then each window of the terrain's own grid from the window grown
// by the detail run's reach (detail_run.hpp). A window is the same bits as
// those samples of the whole, and the whole is computed in bands.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/erosion.hpp"

namespace ft::erosion {

// The terrain's heights before erosion, read by rectangles.
class HeightSource {
 public:
  virtual ~HeightSource() = default;
  // Samples [x0, x0 + w) x [y0, y0 + h) of the grid into out (w x h, row-major);
  // on a periodic grid the positions wrap, on a bounded one they lie inside.
  virtual void read(int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) const = 0;
  // Samples (i step, j step), 0 <= i < w, 0 <= j < h, into out (w x h).
  virtual void read_subgrid(int32_t step, int32_t w, int32_t h, float* out) const;
};

// A heightfield in memory as a source (grid g's size).
class ArraySource : public HeightSource {
 public:
  ArraySource(const D8Grid& g, const float* z) : g_(g), z_(z) {}
  void read(int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) const override;
  void read_subgrid(int32_t step, int32_t w, int32_t h, float* out) const override;

 private:
  D8Grid g_;
  const float* z_;
};

// The model's run and what a window needs of it: every task that computes
// it from the same terrain and settings gets the same bits.
struct LandscapeModel {
  D8Grid g;              // the terrain's grid (its sea is not read)
  bool erodes = false;   // a run of positive length
  bool coarse_to_fine = false;  // not the model's grid (else one run on g itself): through the model's
  double sea_level = NAN;       // the sea's level (NaN: none): samples at or below it stay
  D8Grid coarse, sub;    // the model's grid, and the subgrid of g it averages
  int32_t step = 1, radius = 0;  // the subgrid's step, the box mean's radius on it
  std::vector<float> before, change, crept;  // on the model's grid (crept: with a mask only)
  std::vector<uint8_t> coarse_sea;           // on the model's grid: 1 per sea cell (empty: no sea)
  float top = 0;         // the subgrid's highest sample: no deposit rises above it
  double detail_years = 0;
  int32_t detail_steps = 0, reach = 0;  // the detail run's, and how far it reads
  int64_t origin_x = 0, origin_y = 0;   // Rho8's origin for the detail run
};

// The model's grids for terrain `src` on grid g (m's coarse, sub, step,
// radius, top), its input `before` (the subgrid's box means on the model's
// grid) and its sea `coarse_sea` at `sea_level` (NaN: none).
void coarse_input(const D8Grid& g, const HeightSource& src, double sea_level, LandscapeModel& m);

// The model for terrain `src` on grid g, eroded with c (its model settings,
// mask and rain map) and a sea at `sea_level` (NaN: none). `budget` (may be
// null) adds the model's volumes.
LandscapeModel landscape_model(const D8Grid& g, const HeightSource& src, const ErosionConfig& c, double sea_level,
                               MassBudget* budget, const Progress& progress);

// Samples [x0, x0 + w) x [y0, y0 + h) of the eroded terrain (inside g; on a
// periodic grid they may run past its edges and wrap) into out (w x h).
void landscape_window(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, int64_t x0, int64_t y0,
                      int32_t w, int32_t h, float* out, const Progress& progress);

// OpenMP's thread count set from a requested count (resolve_threads) for a
// scope, and restored after.
class ThreadScope {
 public:
  explicit ThreadScope(int requested);
  ~ThreadScope();
  ThreadScope(const ThreadScope&) = delete;
  ThreadScope& operator=(const ThreadScope&) = delete;

 private:
  int saved_;
};

// Whether erode() with c is the landscape model alone, whose windows
// erode_window computes (the expert passes read the whole grid each pass).
bool erodes_by_windows(const ErosionConfig& c);

// Samples [x0, x0 + w) x [y0, y0 + h) of erode(the terrain src reads, c)
// (m: landscape_model of that terrain with c's sea level) into `after`, and
// of the terrain itself into `before` (both w x h): the same bits as the
// whole's. Throws unless erodes_by_windows(c). Progress: c.progress.
void erode_window(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, int64_t x0, int64_t y0,
                  int32_t w, int32_t h, float* before, float* after);

// erode_window's `after` and erode()'s maps at those samples, each w x h,
// the same bits: slope and curvature of the eroded heights (on the whole's
// grid spacing `spacing`, as erode's maps), eroded and deposited, water
// depth (0: no hydraulic pass by windows) from the window grown by one
// ring; the drainage area, which is global: up to a side of
// DrainageBlocks::whole_side from the whole eroded terrain, computed here
// in bands of rows (the memory of the whole, about 45 bytes a sample);
// beyond, by the pieces the window touches (block_drainage.hpp), from the
// eroded terrain over their regions (the memory of the window grown by the
// halo). Progress: c.progress.
void erode_window_maps(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, double spacing,
                       int64_t x0, int64_t y0, int32_t w, int32_t h, float* after, ErosionMaps& maps);

}  // namespace ft::erosion
