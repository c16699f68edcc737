// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra coastline: the level set of a heightfield as polylines (marching
// squares), optionally drawn over a shaded relief to look at.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/quantile.hpp"
#include "cli/command.hpp"
#include "contour/marching_squares.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "io/polyline_io.hpp"
#include "preview/relief.hpp"

namespace ft::cli::cmd_coastline {
namespace {

struct CoastlineCli {
  std::string in, level = "q0.5", out, preview;
  bool world = false;
};

// Draws the chains onto an RGB image of the heightfield's size: islands red,
// lakes blue, chains ending on the border yellow (1-pixel lines, DDA).
void draw_chains(std::vector<uint8_t>& rgb, int32_t w, int32_t h, const PolylineSet& set) {
  for (int64_t i = 0; i < set.line_count(); ++i) {
    const contour::ChainKind kind = contour::chain_kind(set, i);
    const uint8_t colour[3][3] = {{255, 220, 0}, {220, 20, 20}, {20, 60, 230}};
    const uint8_t* c = colour[int(kind)];
    for (int64_t k = set.line_begin(i); k + 1 < set.line_end(i); ++k) {
      const Vec3 &a = set.points[size_t(k)], &b = set.points[size_t(k + 1)];
      const int steps = 1 + int(std::ceil(2 * std::max(std::fabs(b[0] - a[0]), std::fabs(b[1] - a[1]))));
      for (int s = 0; s <= steps; ++s) {
        const double t = double(s) / steps;
        const long x = std::lround(a[0] + t * (b[0] - a[0])), y = std::lround(a[1] + t * (b[1] - a[1]));
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        std::copy(c, c + 3, rgb.begin() + (size_t(y) * size_t(w) + size_t(x)) * 3);
      }
    }
  }
}

int run(const CoastlineCli& c) {
  const Heightfield hf = io::read_heightfield(c.in);
  const double level = analysis::resolve_level(hf, analysis::parse_level(c.level, "--level"));
  const PolylineSet set = contour::marching_squares(hf, level);
  if (set.line_count() == 0) {
    // An empty file would look like a success (it used to be written
    // without a word): say why there is no coastline, write nothing.
    const HeightStats s = hf.stats();
    const std::string range = "[" + format_number(s.min) + ", " + format_number(s.max) + "]";
    if (level < s.min || level > s.max)
      invalid("--level " + format_number(level) + " is outside the heights of '" + c.in + "', " + range +
              ": there is no coastline; give a level inside that range, or a quantile such as q0.5");
    invalid("no coastline at --level " + format_number(level) + " in '" + c.in + "' (heights " + range +
            "): no cell has samples on both sides of it");
  }
  if (!c.out.empty() && c.world) {
    // World units: x spans the recorded world size, y keeps the same sample
    // spacing, heights share the unit (as the POV-Ray and Blender builders
    // place the terrain).
    if (!(hf.world_size() > 0))
      invalid("--world: '" + c.in + "' records no world size (make it with fracterra terrain --world-size S)");
    const double k = hf.world_size() / double(hf.width() - 1);
    PolylineSet scaled = set;
    for (Vec3& p : scaled.points) p[0] *= k, p[1] *= k;
    io::write_polylines(scaled, c.out);
  } else if (!c.out.empty()) {
    io::write_polylines(set, c.out);
  }
  if (!c.preview.empty()) {
    preview::ReliefOptions ro;
    const HeightStats s = hf.stats();
    ro.sea_fraction = s.max > s.min ? std::clamp((level - s.min) / (s.max - s.min), 0.0, 1.0) : 0.0;
    std::vector<uint8_t> rgb = preview::shaded_relief(hf, ro);
    draw_chains(rgb, hf.width(), hf.height(), set);
    io::write_png_rgb(c.preview, hf.width(), hf.height(), rgb.data());
  }
  int64_t islands = 0, lakes = 0, open = 0;
  for (int64_t i = 0; i < set.line_count(); ++i) {
    const contour::ChainKind k = contour::chain_kind(set, i);
    (k == contour::ChainKind::kIsland ? islands : k == contour::ChainKind::kLake ? lakes : open) += 1;
  }
  const nlohmann::json j = {{"level", level},       {"chains", set.line_count()}, {"vertices", set.vertex_count()},
                            {"islands", islands},   {"lakes", lakes},             {"open_chains", open}};
  std::printf("%s\n", j.dump().c_str());
  return 0;
}

Registration reg({"coastline",
                  "Level set (coastline) of a heightfield as polylines: marching squares, land on the left",
                  [](CLI::App& app) -> std::function<int()> {
                    auto c = std::make_shared<CoastlineCli>();
                    app.add_option("--in", c->in, io::kHeightfieldReadHelp)->required();
                    app.add_option("--level", c->level,
                                   "height of the level set, or a quantile of the samples as qF with F in [0, 1] "
                                   "(q0.5 = the median)")
                        ->capture_default_str();
                    app.add_option("--out", c->out,
                                   "output polylines .csv (x,y,z,radius; blank line between chains) or .json; "
                                   "x = column, y = row, z = level; closed loops repeat their first vertex");
                    app.add_flag("--world", c->world,
                                 "write x, y in world units (the terrain's recorded --world-size across x, same "
                                 "spacing in y) instead of columns and rows");
                    app.add_option("--preview", c->preview,
                                   "also draw the chains over a shaded relief to this RGB .png (islands red, lakes "
                                   "blue, border chains yellow)");
                    return [c] {
                      if (c->out.empty() && c->preview.empty()) invalid("give --out FILE and/or --preview FILE.png");
                      return run(*c);
                    };
                  },
                  50});

}  // namespace
}  // namespace ft::cli::cmd_coastline
