// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra refine: a real DEM refined by midpoint displacement (or random
// additions) from its own samples, with H and sigma measured on it.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "refine/dem_refine.hpp"
#include "refine/dem_refine_params.hpp"

namespace ft::cli::cmd_refine {
namespace {

struct RefineCli {
  std::string in, out, levels = "+2", hurst = "auto", sigma = "auto", window;
  std::string nodata = "avoid";
  // seed, method and threads are flags from the table; the other fields have
  // their own forms here (+K, auto, X,Y[,SIDE]).
  ft_dem_refine_params p = defaults_of<ft_dem_refine_params>(refine::dem_refine_param_table());
};

// "auto" -> `fallback` (the "measure it" value); otherwise a number.
double number_or_auto(const std::string& text, const char* name, double fallback) {
  if (text == "auto") return fallback;
  try {
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  invalid(std::string(name) + " must be auto or a number, got '" + text + "'");
}

int run(RefineCli& o) {
  const std::string k = o.levels.empty() || o.levels[0] != '+' ? o.levels : o.levels.substr(1);
  try {
    size_t used = 0;
    o.p.levels_added = std::stoi(k, &used);
    if (used != k.size()) throw std::invalid_argument(k);
  } catch (const std::exception&) {
    invalid("--levels must be +K, the number of levels to add (1..12), got '" + o.levels + "'");
  }
  // A number given is the value itself: a negative one is not a way to say
  // auto. The rest of each range is the table's (dem_refine_config).
  o.p.hurst = number_or_auto(o.hurst, "--hurst", -1.0);
  if (o.hurst != "auto" && !(o.p.hurst >= 0)) invalid("--hurst must be auto or H >= 0, got " + o.hurst);
  o.p.sigma = number_or_auto(o.sigma, "--sigma", -1.0);
  if (o.sigma != "auto" && !(o.p.sigma > 0)) invalid("--sigma must be auto or > 0, got " + o.sigma);
  if (!o.window.empty()) {
    int x = -1, y = -1, side = 0;
    char tail = 0;
    const int n = std::sscanf(o.window.c_str(), "%d,%d,%d%c", &x, &y, &side, &tail);
    if (n != 2 && n != 3) invalid("--window must be X,Y or X,Y,SIDE (samples), got '" + o.window + "'");
    o.p.window_x = x, o.p.window_y = y;
    if (n == 3) o.p.window_side = side;
  }
  // Nodata: by default the window avoids it; "fill" fills it first (then any
  // window will do), "refuse" refuses a DEM that has any.
  const io::NodataPolicy policy = o.nodata == "fill" ? io::NodataPolicy::fill
                              : o.nodata == "refuse" ? io::NodataPolicy::refuse
                                                     : io::NodataPolicy::keep;
  const refine::DemRefineConfig c = refine::dem_refine_config(o.p);  // the ranges, before the DEM is read
  const Heightfield dem = io::read_heightfield(o.in, policy);
  const refine::DemRefineResult r = refine::refine_dem(dem, c);
  io::write_heightfield(r.terrain, o.out);
  nlohmann::json j = {{"dem", {dem.width(), dem.height()}},
                      {"window", {{"x", r.window_x}, {"y", r.window_y}, {"side", r.window_side}}},
                      {"levels_added", c.levels_added},
                      {"size", r.terrain.width()},
                      {"hurst", r.hurst},
                      {"hurst_measured", r.hurst_measured},
                      {"sigma", r.sigma},
                      {"sigma_measured", r.sigma_measured},
                      {"increment_variance_one_pixel", r.v1},
                      {"world_size", r.terrain.world_size()},
                      {"georeferenced", !r.terrain.georef().empty()}};
  if (r.hurst_measured)
    j["hurst_estimate"] = {{"method", analysis::hurst_method_name(r.estimate.method)},
                           {"hurst", r.estimate.hurst},
                           {"std_error", r.estimate.std_error},
                           {"lags", {r.estimate.band_lo, r.estimate.band_hi}}};
  std::printf("%s\n", j.dump(2).c_str());
  return 0;
}

Registration reg({"refine", "Refine a real DEM: its samples kept, finer levels added with its own H and sigma",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<RefineCli>();
                    app.add_option("--in", o->in, "the DEM: any raster GDAL reads (GeoTIFF, .hgt, .asc, ...)")
                        ->required()
                        ->check(existing_file);
                    app.add_option("--out", o->out, std::string("the refined terrain: ") + io::kHeightfieldWriteFormats +
                                                        " (.tif keeps the georeference)")
                        ->required();
                    app.add_option("--levels", o->levels, "+K: levels added (1..12); the side grows 2^K times")
                        ->capture_default_str();
                    app.add_option("--hurst", o->hurst, "auto (the DEM's variogram slope) or H in [0, 0.99]")
                        ->capture_default_str();
                    app.add_option("--sigma", o->sigma,
                                   "auto (from the DEM's increments at one pixel) or the vertical scale > 0")
                        ->capture_default_str();
                    add_param_flags(app, refine::dem_refine_param_table(), &o->p,
                                    {"levels_added", "hurst", "sigma", "window_x", "window_y", "window_side"});
                    app.add_option("--window", o->window,
                                   "X,Y[,SIDE]: the window's top-left sample (and side 2^m + 1); default: the "
                                   "largest without nodata, nearest the centre");
                    app.add_option("--nodata", o->nodata,
                                   "avoid (the window holds none), fill (GDAL's inverse-distance fill) or refuse")
                        ->check(CLI::IsMember({"avoid", "fill", "refuse"}))
                        ->capture_default_str();
                    return [o] { return run(*o); };
                  },
                  35});

}  // namespace
}  // namespace ft::cli::cmd_refine
