// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/terrain_build.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "erosion/erosion_params.hpp"
#include "erosion/landscape_window.hpp"
#include "erosion/presets.hpp"
#include "hydrology/hydrology_params.hpp"
#include "pipeline/build_params.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_method.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::pipeline {
namespace {

// Weights of the stages on the one progress bar (erosion is the longest;
// rivers take about as long as generating).
constexpr double kGenerationWeight = 0.25, kErosionWeight = 0.75, kRiversWeight = 0.1;

// A stage's share [start, start + span) of the build's one progress bar.
struct Span {
  Progress outer;
  double start, span;
  static int32_t call(void* self, double f) {
    auto* s = static_cast<Span*>(self);
    try {
      s->outer.report(s->start + s->span * f);
    } catch (const Error&) {
      return 1;
    }
    return 0;
  }
};

bool erodes(const ft_build_params& p) { return p.erosion || p.erosion_preset != FT_EROSION_PRESET_NONE; }

// A preset sets which processes run (its pass counts, all three) and every
// setting it changes from the defaults (the uplift fitted to the terrain):
// what `fracterra erode --preset` gives without further flags, and what the
// add-on's presets always did. The other settings stay as given.
ft_erosion_params apply_preset(const ft_erosion_params& given, const ft_erosion_params& preset) {
  static const ft_erosion_params defaults = defaults_of<ft_erosion_params>(erosion::erosion_param_table());
  ft_erosion_params out = given;
  for (const ft_param_info& row : erosion::erosion_param_table().rows) {
    if (row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) continue;
    const auto* from = reinterpret_cast<const char*>(&preset) + row.offset;
    if (std::memcmp(from, reinterpret_cast<const char*>(&defaults) + row.offset, row.size) != 0)
      std::memcpy(reinterpret_cast<char*>(&out) + row.offset, from, row.size);
  }
  out.fluvial_steps = preset.fluvial_steps;
  out.hydraulic_iterations = preset.hydraulic_iterations;
  out.thermal_iterations = preset.thermal_iterations;
  return out;
}

// A dyadic periodic grid (period_overlap 1) repeats its first row and column
// as the last: its torus is the grid without them, (W - 1) x (H - 1), at the
// same spacing.
Heightfield torus_of(const Heightfield& hf, int overlap) {
  const int w = hf.width() - overlap, h = hf.height() - overlap;
  Heightfield t(w, h);
  for (int j = 0; j < h; ++j) std::memcpy(t.data() + size_t(j) * w, hf.data() + size_t(j) * hf.width(), sizeof(float) * w);
  if (hf.world_size() > 0) t.set_world_size(hf.world_size() * double(w - 1) / double(hf.width() - 1));
  return t;
}

// The torus back on the full grid: row and column 0 copied to the last, so it still tiles.
Heightfield untorus(const Heightfield& t, int overlap, double world_size) {
  const int w = t.width() + overlap, h = t.height() + overlap;
  Heightfield hf(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) hf.data()[size_t(j) * w + i] = t.at(i % t.width(), j % t.height());
  hf.set_world_size(world_size);
  return hf;
}

// The erode stage's settings for a terrain of `world` (null: the erosion's own periodic and sea
// fields): one rule for every front end, a terrain that tiles erodes as a torus, and the
// landform's sea is erosion's base level (rivers end in it and its floor stays flat; before, the
// rivers' sediment built it up into sand flats and specks).
ft_erosion_params stage_erosion(const ft_build_params& p, const Heightfield& hf, const ft_terrain_world* world);

// A world as the C ABI takes it: checked, or refused with what is allowed.
void check_world(const ft_terrain_world* world, const Heightfield& hf) {
  if (!world) return;
  if (world->struct_size < sizeof(ft_terrain_world))
    invalid("ft_terrain_world.struct_size is " + std::to_string(world->struct_size) + "; set it with ft_terrain_world_init");
  if (world->period_overlap < -1 || world->period_overlap > 1)
    invalid("ft_terrain_world.period_overlap must be -1 (does not tile), 0 or 1, got " +
            std::to_string(world->period_overlap));
  if (world->period_overlap > 0 && (hf.width() < 3 || hf.height() < 3))
    invalid("a terrain whose last row and column repeat the first needs at least 3 x 3 samples");
  if (std::isinf(world->sea_level)) invalid("ft_terrain_world.sea_level must be finite, or NaN for no sea");
}

// A made terrain as the stages take it: `hf` itself, or (a world size of 0: a file that records
// none) a copy of it in a world of 10 units, held in `copy`.
const Heightfield& with_world_size(const Heightfield& hf, Heightfield& copy) {
  if (hf.world_size() > 0) return hf;
  copy = Heightfield(hf.width(), hf.height());
  std::memcpy(copy.data(), hf.data(), sizeof(float) * hf.size());
  copy.set_georef(hf.georef());
  copy.set_world_size(10.0);
  return copy;
}

}  // namespace

ft_erosion_params erosion_settings(const ft_erosion_params* given, const std::string& preset,
                                    const Heightfield& terrain) {
  const ft_erosion_params e = given ? upgraded(erosion::erosion_param_table(), *given)
                                    : defaults_of<ft_erosion_params>(erosion::erosion_param_table());
  if (preset.empty()) return e;
  return apply_preset(e, erosion::to_c(erosion::erosion_preset(preset, terrain)));
}

namespace {
ft_erosion_params stage_erosion(const ft_build_params& p, const Heightfield& hf, const ft_terrain_world* world) {
  ft_erosion_params e = erosion_settings(p.erosion, erosion_preset_name(p.erosion_preset), hf);
  if (world) {
    e.periodic = world->period_overlap >= 0;
    if (!std::isnan(world->sea_level)) e.sea = FT_WATER_SEA_HEIGHT, e.sea_level = world->sea_level;
  }
  e.threads = p.threads;
  return e;
}
}  // namespace

Heightfield erode_terrain(const Heightfield& hf, const ft_erosion_params& e, int overlap, erosion::ErosionMaps* maps,
                          erosion::MassBudget* budget) {
  const erosion::ErosionConfig c = erosion::from_c(e);
  if (!c.periodic || overlap == 0) return erosion::erode(hf, c, maps, budget);
  const double world_size = hf.world_size();
  const Heightfield eroded = erosion::erode(torus_of(hf, overlap), c, maps, budget);
  if (maps)
    for (Heightfield* m : maps->all()) *m = untorus(*m, overlap, world_size);
  return untorus(eroded, overlap, world_size);
}

hydrology::HydrologyConfig build_rivers_config(const ft_build_params& p, const ft_terrain_params& t) {
  ft_hydrology_params h = p.rivers ? *p.rivers : defaults_of<ft_hydrology_params>(hydrology::hydrology_param_table());
  h.progress = nullptr, h.progress_user = nullptr;
  hydrology::HydrologyConfig c = hydrology::from_c(h);
  if (t.sea != FT_SEA_NONE) {
    // The landform flattened this sea: the rivers end in it (its level: build_terrain).
    c.sea = hydrology::Sea(t.sea);
    c.sea_level = t.sea_level;
    c.sea_fraction = t.sea_fraction;
  }
  // One rule for every front end: a terrain that tiles is a torus.
  c.periodic = terrain::tiles_periodically(t);
  c.threads = p.threads;
  return c;
}

Heightfield build_terrain(const ft_build_params& given, erosion::ErosionMaps* maps, hydrology::RiverNetwork* rivers,
                          ft_terrain_world* world_out) {
  const ft_build_params p = upgraded(build_param_table(), given);
  check_ranges(build_param_table(), &p);
  check_not_null("terrain", p.terrain);
  ft_terrain_params t = upgraded(terrain::terrain_param_table(), *p.terrain);
  t.threads = p.threads;
  // Everything is checked before any work: the terrain, then the erosion
  // settings (their ranges; the preset's name is the table's), the rivers'.
  terrain::validate_terrain_params(t);
  const bool erode = erodes(p) || maps;
  if (erode) erosion::from_c(erosion_settings(p.erosion, "", Heightfield()));  // (no preset: no terrain read)
  hydrology::HydrologyConfig rc;
  if (rivers) rc = build_rivers_config(p, t);

  const Progress progress(p.progress, p.progress_user);
  const double total = kGenerationWeight + (erode ? kErosionWeight : 0.0) + (rivers ? kRiversWeight : 0.0);
  double done = 0;
  auto span = [&](double weight) {
    const Span s{progress, done / total, weight / total};
    done += weight;
    return s;
  };
  Span generation = span(kGenerationWeight);
  t.progress = &Span::call, t.progress_user = &generation;
  Heightfield hf = terrain::generate_terrain(t);  // with its landform
  // Where the landform flattened its sea (a fraction: at the lowest height).
  const double sea_z = t.sea == FT_SEA_HEIGHT ? t.sea_level : t.sea == FT_SEA_FRACTION ? hf.stats().min : 0.0;
  const int overlap = terrain::tiles_periodically(t) ? terrain::terrain_method(t.method).period_overlap : 0;
  ft_terrain_world world{sizeof(ft_terrain_world), terrain::tiles_periodically(t) ? overlap : -1,
                         t.sea != FT_SEA_NONE ? sea_z : NAN};
  if (world_out) *world_out = world;
  if (erode) {
    ft_erosion_params e = stage_erosion(p, hf, &world);
    Span erosion_span = span(kErosionWeight);
    e.progress = &Span::call, e.progress_user = &erosion_span;
    hf = erode_terrain(hf, e, e.periodic ? overlap : 0, maps);
  }
  if (rivers) {
    // The rivers of what was made, on the torus it was eroded on.
    if (t.sea != FT_SEA_NONE) {
      // The rivers' sea is the landform's flat sea, as a height (a fraction
      // of the eroded heights would move it), which erosion left as it was.
      const HeightStats st = hf.stats();
      rc.sea = hydrology::Sea::kHeight;
      rc.sea_level = std::clamp(sea_z, double(st.min), double(st.max));
    }
    Span rivers_span = span(kRiversWeight);
    rc.progress = Progress(&Span::call, &rivers_span);
    // The ground under each river is carved to its depth (never below the
    // sea), so no river lies flush with the ground it runs on.
    if (overlap == 0) {
      *rivers = hydrology::extract_rivers(hf, rc);
      hf = hydrology::carve(hf, *rivers);
    } else {
      const double world_size = hf.world_size();
      const Heightfield torus = torus_of(hf, overlap);
      *rivers = hydrology::extract_rivers(torus, rc);
      hf = untorus(hydrology::carve(torus, *rivers), overlap, world_size);
    }
  }
  return hf;
}

Heightfield erode_made(const ft_build_params& given, const Heightfield& made, const ft_terrain_world* world,
                       erosion::ErosionMaps* maps) {
  const ft_build_params p = upgraded(build_param_table(), given);
  check_ranges(build_param_table(), &p);
  check_world(world, made);
  Heightfield copy;
  const Heightfield& hf = with_world_size(made, copy);
  ft_erosion_params e = stage_erosion(p, hf, world);
  e.progress = p.progress, e.progress_user = p.progress_user;
  return erode_terrain(hf, e, world && e.periodic ? std::max(0, world->period_overlap) : 0, maps);
}

hydrology::RiverNetwork rivers_made(const ft_build_params& given, const Heightfield& made,
                                    const ft_terrain_world* world) {
  const ft_build_params p = upgraded(build_param_table(), given);
  check_ranges(build_param_table(), &p);
  check_world(world, made);
  Heightfield copy;
  const Heightfield& hf = with_world_size(made, copy);
  ft_hydrology_params h = p.rivers ? *p.rivers : defaults_of<ft_hydrology_params>(hydrology::hydrology_param_table());
  h.progress = nullptr, h.progress_user = nullptr;
  hydrology::HydrologyConfig c = hydrology::from_c(h);
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  int overlap = 0;
  if (world) {
    // build_terrain's rules: the torus it was eroded on, its own sea as a height.
    c.periodic = world->period_overlap >= 0;
    overlap = std::max(0, world->period_overlap);
    if (!std::isnan(world->sea_level)) {
      const HeightStats st = hf.stats();
      c.sea = hydrology::Sea::kHeight;
      c.sea_level = std::clamp(world->sea_level, double(st.min), double(st.max));
    }
  }
  return overlap == 0 ? hydrology::extract_rivers(hf, c) : hydrology::extract_rivers(torus_of(hf, overlap), c);
}

namespace {

// The generated terrain (with its landform) as erosion's source, by
// generation windows: the whole's samples, on the grid erosion takes (a
// dyadic torus without its repeated last row and column).
class GeneratedSource : public erosion::HeightSource {
 public:
  GeneratedSource(const ft_terrain_params& t, const erosion::D8Grid& g) : t_(t), g_(g) {
    t_.progress = nullptr, t_.progress_user = nullptr;
  }
  void read(int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) const override {
    // In pieces that do not cross a periodic grid's edge.
    for (int32_t j = 0; j < h;) {
      const int64_t y = wrapped(y0 + j, g_.height);
      const int32_t rows = int32_t(std::min<int64_t>(h - j, g_.height - y));
      for (int32_t i = 0; i < w;) {
        const int64_t x = wrapped(x0 + i, g_.width);
        const int32_t cols = int32_t(std::min<int64_t>(w - i, g_.width - x));
        const Heightfield piece = terrain::generate_terrain_window(t_, 0, x, y, cols, rows);
        for (int32_t r = 0; r < rows; ++r)
          std::memcpy(out + size_t(j + r) * w + i, piece.data() + size_t(r) * cols, sizeof(float) * cols);
        i += cols;
      }
      j += rows;
    }
  }
  void read_subgrid(int32_t step, int32_t w, int32_t h, float* out) const override {
    // A level of detail is every 2^lod-th sample of the whole (for midpoint,
    // exactly its coarser stage: it costs that stage).
    const int lod = std::countr_zero(uint32_t(step));
    if (!terrain::terrain_method(t_.method).lod || (int32_t(1) << lod) != step)
      return erosion::HeightSource::read_subgrid(step, w, h, out);
    const Heightfield sub = terrain::generate_terrain_window(t_, lod, 0, 0, w, h);
    std::memcpy(out, sub.data(), sizeof(float) * size_t(w) * h);
  }

 private:
  int64_t wrapped(int64_t v, int64_t n) const { return g_.periodic ? ((v % n) + n) % n : v; }
  ft_terrain_params t_;
  erosion::D8Grid g_;
};

// Samples [x0, x0 + w) x [y0, y0 + h) of `hf`, with the window's share of its world size.
Heightfield crop(const Heightfield& hf, int64_t x0, int64_t y0, int32_t w, int32_t h) {
  Heightfield out(w, h);
  for (int32_t j = 0; j < h; ++j)
    std::memcpy(out.data() + size_t(j) * w, hf.data() + size_t(y0 + j) * hf.width() + size_t(x0), sizeof(float) * w);
  if (hf.world_size() > 0) out.set_world_size(hf.world_size() * double(w - 1) / double(hf.width() - 1));
  return out;
}

}  // namespace

Heightfield build_terrain_window(const ft_build_params& given, int64_t x0, int64_t y0, int32_t w, int32_t h,
                                 erosion::ErosionMaps* maps) {
  const ft_build_params p = upgraded(build_param_table(), given);
  check_ranges(build_param_table(), &p);
  check_not_null("terrain", p.terrain);
  // The terrain's window rules first (no spectral, no sea fraction), then the window itself.
  ft_terrain_params t = upgraded(terrain::terrain_param_table(), *p.terrain);
  t.threads = p.threads;
  int64_t ew = 0, eh = 0;
  terrain::terrain_extent(t, 0, &ew, &eh);
  if (w < 1 || h < 1)
    invalid("a window needs at least 1 x 1 samples, got " + std::to_string(w) + " x " + std::to_string(h));
  if (x0 < 0 || y0 < 0 || x0 > ew - w || y0 > eh - h)
    invalid("the window [" + std::to_string(x0) + ", " + std::to_string(x0 + w) + ") x [" + std::to_string(y0) +
            ", " + std::to_string(y0 + h) + ") lies outside the terrain's " + std::to_string(ew) + " x " +
            std::to_string(eh) + " samples");
  // Maps are of an eroded terrain: without erosion settings, the defaults' (build_terrain's rule).
  const bool erode = erodes(p) || maps;
  ft_erosion_params e;
  if (erode) {
    // The presets are in world units and years: nothing of the terrain to fit.
    e = erosion_settings(p.erosion, erosion_preset_name(p.erosion_preset), Heightfield());
    e.periodic = terrain::tiles_periodically(t);
    e.threads = p.threads;
    if (t.sea == FT_SEA_HEIGHT) e.sea = FT_WATER_SEA_HEIGHT, e.sea_level = t.sea_level;
  }
  const erosion::ErosionConfig c = erode ? erosion::from_c(e) : erosion::ErosionConfig();
  if (erode && !erosion::erodes_by_windows(c)) {
    // The expert passes read the whole grid: the whole, cropped (exact by construction).
    erosion::ErosionMaps whole_maps;
    const Heightfield whole = build_terrain(p, maps ? &whole_maps : nullptr);
    if (maps) {
      const auto from = whole_maps.all(), to = maps->all();
      for (size_t k = 0; k < to.size(); ++k) *to[k] = crop(*from[k], x0, y0, w, h);
    }
    return crop(whole, x0, y0, w, h);
  }
  if (!erode) {
    // Generation alone: the terrain's own windows, in memory of the window.
    t.progress = p.progress, t.progress_user = p.progress_user;
    return terrain::generate_terrain_window(t, 0, x0, y0, w, h);
  }
  // The landscape model by windows, on the grid erode_terrain erodes: a
  // dyadic torus without its repeated last row and column.
  erosion::validate_settings(c);
  const int overlap = c.periodic ? terrain::terrain_method(t.method).period_overlap : 0;
  erosion::D8Grid g;
  g.width = int32_t(ew) - overlap, g.height = int32_t(eh) - overlap;
  g.periodic = c.periodic;
  g.spacing = t.world_size / double(ew - 1);
  const GeneratedSource src(t, g);
  const erosion::ThreadScope threads(p.threads);
  const Progress progress(p.progress, p.progress_user);
  // With maps, the drainage area's whole takes most of the bar.
  const double model_share = maps ? 0.1 : 0.4;
  const ProgressPart model_part(progress, 0.0, model_share), window_part(progress, model_share, 1.0 - model_share);
  const double sea_level = c.sea == erosion::Sea::kHeight ? c.sea_level : NAN;
  const erosion::LandscapeModel m = erosion::landscape_model(g, src, c, sea_level, nullptr, model_part.progress());
  erosion::ErosionConfig wc = c;
  wc.progress = window_part.progress();
  Heightfield out(w, h);
  if (!maps) {
    std::vector<float> before(size_t(w) * h);
    erosion::erode_window(m, src, wc, x0, y0, w, h, before.data(), out.data());
  } else {
    // The maps on erode()'s grid: its spacing as grid_of gives it on the
    // torus erode_terrain cuts (the same bits, so the same areas and slopes).
    const double spacing =
        overlap > 0 ? t.world_size * double(g.width - 1) / double(ew - 1) / (g.width - 1) : t.world_size / (ew - 1);
    erosion::erode_window_maps(m, src, wc, spacing, x0, y0, w, h, out.data(), *maps);
    for (Heightfield* f : maps->all()) f->set_world_size(t.world_size * double(w - 1) / double(ew - 1));
  }
  out.set_world_size(t.world_size * double(w - 1) / double(ew - 1));
  progress.report(1.0);
  return out;
}
}  // namespace ft::pipeline
