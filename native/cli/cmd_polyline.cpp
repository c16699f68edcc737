// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra polyline: fractal polylines (FPL 2D/3D, lightning, Koch, dragon,
// Sierpinski arrowhead, IFS, Voss profile) as CSV/JSON, an optional SVG
// drawing, and the measures of seed 003 as JSON.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/polyline_report.hpp"
#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/polyline_io.hpp"
#include "io/svg_plot.hpp"
#include "polyline/polyline.hpp"
#include "polyline/polyline_params.hpp"
#include "povray/render.hpp"
#include "povray/scene.hpp"

namespace ft::cli::cmd_polyline {
namespace {

const std::map<std::string, int> kKinds = {{"line", int(pov::LineKind::kGeneric)},
                                           {"lightning", int(pov::LineKind::kLightning)},
                                           {"coastline", int(pov::LineKind::kCoastline)}};

struct PolylineOptions {
  ft_polyline_params p = polyline::default_polyline_params();
  std::string base, normal, ifs_table, out, svg, pov, render;
  int kind = -1;  // -1: lightning when the line branches, else line
  pov::RenderOptions r;
  bool stats = false;
};

// Numbers separated by commas (and spaces), e.g. "0.5,1,0".
std::vector<double> parse_numbers(const std::string& text, const std::string& what) {
  std::vector<double> v;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ',')) {
    const auto a = item.find_first_not_of(" \t"), b = item.find_last_not_of(" \t");
    if (a == std::string::npos) invalid(what + ": empty number in '" + text + "'");
    item = item.substr(a, b - a + 1);
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0') invalid(what + ": '" + item + "' is not a number");
    v.push_back(x);
  }
  return v;
}

// "x0,y0[,z0];x1,y1[,z1];..." -> xyz triples.
std::vector<double> parse_base(const std::string& text) {
  std::vector<double> xyz;
  std::string point;
  std::istringstream in(text);
  int i = 0;
  while (std::getline(in, point, ';')) {
    ++i;
    const std::vector<double> v = parse_numbers(point, "--base point " + std::to_string(i));
    if (v.size() < 2 || v.size() > 3)
      invalid("--base point " + std::to_string(i) + " must be x,y or x,y,z, got '" + point + "'");
    xyz.insert(xyz.end(), {v[0], v[1], v.size() == 3 ? v[2] : 0.0});
  }
  return xyz;
}

// An IFS table file: one map per line "a,b,c,d,e,f,p" ('#' comments).
std::vector<double> read_ifs_table(const std::string& path) {
  std::vector<double> t;
  std::istringstream in(io::read_file(path));
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto a = line.find_first_not_of(" \t\r");
    if (a == std::string::npos || line[a] == '#') continue;
    if (line.back() == '\r') line.pop_back();
    const std::vector<double> v = parse_numbers(line, "'" + path + "' line " + std::to_string(n));
    if (v.size() != 7) invalid("'" + path + "' line " + std::to_string(n) + ": expected a,b,c,d,e,f,p");
    t.insert(t.end(), v.begin(), v.end());
  }
  return t;
}

int run(const PolylineOptions& o) {
  ft_polyline_params p = o.p;
  std::vector<double> base, table;
  if (!o.base.empty()) {
    base = parse_base(o.base);
    p.base = base.data();
    p.base_count = int64_t(base.size() / 3);
  }
  if (!o.normal.empty()) {
    const std::vector<double> n = parse_numbers(o.normal, "--normal");
    if (n.size() != 3) invalid("--normal must be x,y,z");
    for (int k = 0; k < 3; ++k) p.plane_normal[k] = n[size_t(k)];
  }
  if (!o.ifs_table.empty()) {
    table = read_ifs_table(o.ifs_table);
    p.ifs_table = table.data();
    p.ifs_maps = int32_t(table.size() / 7);
  }
  Stopwatch clock;
  const PolylineSet set = polyline::generate_polylines(p);
  const double seconds = clock.seconds();
  if (!o.out.empty()) io::write_polylines(set, o.out);
  if (!o.svg.empty()) io::write_file_atomically(o.svg, io::render_polylines_svg(set, 900, 600, p.branch_prob > 0));
  if (!o.pov.empty()) {
    // Framed on the line over a plain ground, its tube sized from the
    // picture (the vertex radii keep only the taper of the branches).
    pov::SceneLines l;
    l.set = &set;
    l.kind = pov::LineKind(o.kind >= 0 ? o.kind : p.branch_prob > 0 ? int(pov::LineKind::kLightning)
                                                                    : int(pov::LineKind::kGeneric));
    l.radii_in_world_units = false;
    pov::CameraOptions camera = pov::polyline_camera(l.kind);
    camera.aspect = double(o.r.width) / double(o.r.height);
    pov::write_polyline_scene(l, o.pov, camera, o.r.width);
    if (!o.render.empty()) {
      const auto res = pov::render_scene(o.pov, o.render, o.r);
      if (res.warnings > 0) std::fputs(res.messages.c_str(), stderr);
    }
  }
  if (o.stats) {
    nlohmann::json j = analysis::polyline_report(set);
    j["seconds"] = seconds;
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"polyline", "Generate a fractal polyline (FPL, lightning, Koch, dragon, Sierpinski, IFS)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<PolylineOptions>();
                    // Every setting of ft_polyline_params from its table; the base polyline,
                    // the plane normal and an IFS table have their own forms below. --ifs and
                    // --points are the names these flags had before the table.
                    add_param_flags(app, polyline::polyline_param_table(), &o->p, {},
                                    {{"ifs_preset", "--ifs"}, {"ifs_points", "--points"}});
                    app.add_option("--base", o->base,
                                   "base polyline \"x0,y0[,z0];x1,y1[,z1];...\" (>= 2 points, consecutive ones "
                                   "distinct); default the unit segment 0,0;1,0");
                    app.add_option("--normal", o->normal,
                                   "fpl3d: displace within the plane of this normal \"x,y,z\" (plane_normal); "
                                   "default: a random perpendicular direction per midpoint");
                    app.add_option("--ifs-table", o->ifs_table,
                                   "ifs: a file of maps, one \"a,b,c,d,e,f,p\" per line: x' = a x + b y + e, "
                                   "y' = c x + d y + f, probability p (instead of --ifs-preset)")
                        ->check(existing_file);
                    app.add_option("--out", o->out, "output .csv (x,y,z,radius; blank line between polylines) or .json");
                    app.add_option("--svg", o->svg, "also draw the x,y projection into this .svg");
                    app.add_option("--pov", o->pov,
                                   "also write a POV-Ray scene of the polylines (.pov): framed, over a plain ground, "
                                   "the tube sized to show the detail at --width");
                    app.add_option("--kind", o->kind, "--pov: draw as line, lightning (glowing) or coastline; "
                                                      "default lightning when --branch-prob > 0, else line")
                        ->transform(choice(kKinds));
                    app.add_option("--render", o->render, "--pov: also render the scene with povray to this PNG");
                    app.add_option("--width", o->r.width, "--pov/--render: image width in pixels (framing, radius)")
                        ->check(CLI::Range(16, 16384))->capture_default_str();
                    app.add_option("--height", o->r.height, "--pov/--render: image height in pixels")
                        ->check(CLI::Range(16, 16384))->capture_default_str();
                    app.add_flag("--stats", o->stats,
                                 "print JSON: eta, chi, gamma (of line 0, relative to its chord), mass and "
                                 "box-counting dimensions, seconds");
                    return [o] {
                      if (!o->render.empty() && o->pov.empty()) invalid("--render needs --pov FILE (the scene it renders)");
                      if (o->out.empty() && o->svg.empty() && o->pov.empty() && !o->stats)
                        invalid("give --out FILE, --svg FILE, --pov FILE and/or --stats");
                      return run(*o);
                    };
                  },
                  30});

}  // namespace
}  // namespace ft::cli::cmd_polyline
