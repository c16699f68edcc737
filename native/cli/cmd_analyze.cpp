// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra analyze: measure H and D of a heightfield, a profile or a set of
// polylines, print a JSON report, and optionally plot the log-log fits.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/analysis_params.hpp"
#include "analysis/box_counting.hpp"
#include "analysis/hurst.hpp"
#include "analysis/hurst_choice.hpp"
#include "analysis/polyline_report.hpp"
#include "analysis/quantile.hpp"
#include "cli/cli_util.hpp"
#include "cli/network_json.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/plot_writer.hpp"
#include "core/error.hpp"
#include "erosion/drainage_stats.hpp"
#include "hydrology/hydrology_params.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "contour/marching_squares.hpp"
#include "io/npy.hpp"
#include "io/polyline_io.hpp"
#include "io/svg_plot.hpp"

namespace ft::cli::cmd_analyze {
namespace {

using nlohmann::json;

struct AnalyzeCli {
  std::string file, plot, method = "auto";
  analysis::HurstOptions band;  // only the band fields are used, from `params` once checked
  // The band flags come from ft_hurst_params' table; the estimator and the
  // transect median are --method's own form (every estimator runs).
  ft_hurst_params params = defaults_of<ft_hurst_params>(analysis::hurst_param_table());
  bool drainage = false, periodic = false, rivers = false;
  // --rivers: the network's channel-head area and sea, from ft_hydrology_params' table.
  ft_hydrology_params network = defaults_of<ft_hydrology_params>(hydrology::hydrology_param_table());
};

// Hack's law and slope-area concavity of a heightfield (erosion/drainage_stats.hpp).
json drainage_report(const Heightfield& hf, bool periodic) {
  const erosion::DrainageStats s = erosion::drainage_stats(hf, periodic);
  return {{"hack_h", s.hack_h},         {"hack_h_stderr", s.hack_h_stderr}, {"hack_bins", s.hack_bins},
          {"theta", s.theta},           {"theta_stderr", s.theta_stderr},   {"theta_bins", s.theta_bins},
          {"min_area", s.min_area},     {"max_area", s.max_area},   {"theta_min_area", s.theta_min_area},
          {"note", "real landscapes: Hack h about 0.5-0.6, theta about 0.35-0.7; areas in world units^2; "
                   "lakes count in neither fit, theta is fitted from the slope-area turnover (theta_min_area) up"}};
}

const std::vector<analysis::HurstMethod> kAllMethods = {analysis::HurstMethod::kVariogramAligned, analysis::HurstMethod::kVariogram,
                                              analysis::HurstMethod::kMadogramAligned, analysis::HurstMethod::kMadogram,
                                              analysis::HurstMethod::kSpectral};

// One estimate, for the report and the plot.
struct Named {
  std::string name;
  analysis::HurstEstimate e;
};

json estimate_json(const analysis::HurstEstimate& e) {
  json j = {{"hurst", e.hurst},
            {"dimension", e.dimension},
            {"std_error", e.std_error},
            {"band", {{"unit", analysis::hurst_method_uses_lags(e.method) ? "lag (samples)" : "frequency (cycles per record)"},
                      {"lo", e.band_lo},
                      {"hi", e.band_hi}}},
            {"points", e.fit.points},
            {"slope", e.fit.slope},
            {"intercept", e.fit.intercept}};
  if (e.transects) j["transects"] = e.transect_count, j["transect_method"] = analysis::hurst_method_name(e.method);
  return j;
}

// Every estimator on a profile (surface = nullptr) or a surface. A method
// that cannot run on this input (band too narrow, ...) reports its error.
json hurst_report(const float* profile, size_t n, const Heightfield* surface, const AnalyzeCli& c,
                  std::vector<Named>& fits) {
  json methods = json::object();
  auto run = [&](const std::string& name, analysis::HurstOptions o) {
    try {
      analysis::HurstEstimate e = surface ? analysis::estimate_hurst_surface(*surface, o) : analysis::estimate_hurst_profile(profile, n, o);
      methods[name] = estimate_json(e);
      fits.push_back({name, std::move(e)});
    } catch (const Error& err) {
      methods[name] = {{"error", err.what()}};
    }
  };
  for (analysis::HurstMethod m : kAllMethods) {
    analysis::HurstOptions o = c.band;
    o.method = m;
    run(analysis::hurst_method_name(m), o);
  }
  // The recommendation is the library's (FT_HURST_AUTO), so Blender's measure
  // operator reports the same H. The transect median uses the aligned
  // variogram on dyadic grids, the plain one otherwise.
  const analysis::HurstChoice choice = surface ? analysis::choose_hurst_method(surface->width(), surface->height())
                                     : analysis::choose_hurst_method(int64_t(n), 1);
  if (surface) {
    analysis::HurstOptions o = c.band;
    o.method = choice.reason == analysis::HurstChoiceReason::kDyadicGrid ? analysis::HurstMethod::kVariogramAligned
                                                                : analysis::HurstMethod::kVariogram;
    o.transects = true;
    run("transect_median", o);
  }
  const std::string pick = c.method != "auto" ? c.method : analysis::hurst_method_name(choice.method);
  if (!methods.contains(pick)) invalid("--method '" + pick + "' is not one of the estimators run on this input");
  json report;
  if (methods[pick].contains("error")) {
    report["hurst"] = nullptr, report["dimension"] = nullptr;
  } else {
    report["hurst"] = methods[pick]["hurst"], report["dimension"] = methods[pick]["dimension"];
  }
  report["recommended"] = pick;
  if (c.method == "auto") report["recommended_because"] = choice.why;
  report["methods"] = methods;
  return report;
}

json box_json(const analysis::BoxCountResult& b) {
  return {{"dimension", b.dimension}, {"std_error", b.std_error}, {"min_size", b.min_size},
          {"max_size", b.max_size},   {"sizes", b.sizes},       {"counts", b.counts}};
}

// The median coastline of a heightfield and its box-counting dimension:
// a second, independent reading of H through D = 2 - H (seed 001). Boxes
// from 4 cells (finer ones see the straight marching-squares chords) to the
// box counter's default E / 4.
json coastline_report(const Heightfield& hf, analysis::BoxCountResult* out) {
  try {
    const double level = analysis::heightfield_quantile(hf, 0.5);
    const PolylineSet set = contour::marching_squares(hf, level);
    analysis::BoxCountOptions o;
    o.min_size = 4;
    const analysis::BoxCountResult b = analysis::box_counting_dimension(set, o);
    if (out) *out = b;
    return {{"level", level},         {"quantile", 0.5},       {"chains", set.line_count()},
            {"box_counting", box_json(b)}, {"hurst", 2 - b.dimension}};
  } catch (const Error& e) {
    return {{"error", e.what()}};
  }
}

// A log-log panel: the measured points and the fitted power law over them.
io::SvgPanel fit_panel(const std::string& title, const std::string& xl, const std::string& yl,
                   const std::vector<double>& x, const std::vector<double>& y, double slope, double intercept,
                   const std::string& fit_label) {
  io::SvgPanel p;
  p.title = title, p.x_label = xl, p.y_label = yl, p.log_x = p.log_y = true;
  io::SvgSeries data;
  data.label = "measured", data.x = x, data.y = y, data.line = false, data.points = true;
  io::SvgSeries fit;
  fit.label = fit_label, fit.dashed = true;
  for (double v : x) fit.x.push_back(v), fit.y.push_back(std::exp(intercept) * std::pow(v, slope));
  p.series = {data, fit};
  return p;
}

io::SvgPanel estimate_panel(const Named& n) {
  const analysis::HurstEstimate& e = n.e;
  char label[96];
  std::snprintf(label, sizeof label, "H = %.3f +- %.3f, D = %.3f", e.hurst, e.std_error, e.dimension);
  const bool lags = analysis::hurst_method_uses_lags(e.method);
  const bool mad = e.method == analysis::HurstMethod::kMadogram || e.method == analysis::HurstMethod::kMadogramAligned;
  std::string title = n.name;
  if (e.transects) title += " (median transect)";
  return fit_panel(title, lags ? "lag (samples)" : "frequency (cycles per record)",
                   lags ? (mad ? "E|dX|" : "0.5 E[dX^2]") : "power", e.x, e.y, e.fit.slope, e.fit.intercept, label);
}

io::SvgPanel box_panel(const std::string& title, const std::vector<double>& sizes, const std::vector<int64_t>& counts,
                   double dimension, double std_error) {
  std::vector<double> x(sizes), y(counts.begin(), counts.end());
  // Fit line through the centroid of the logs with slope -D.
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]) / double(x.size()), my += std::log(y[i]) / double(x.size());
  char label[96];
  std::snprintf(label, sizeof label, "D = %.3f +- %.3f", dimension, std_error);
  return fit_panel(title, "box size", "boxes hit N", x, y, -dimension, my + dimension * mx, label);
}

int run(const AnalyzeCli& c) {
  const std::string ext = io::extension_of(c.file);
  json report = {{"file", c.file}};
  std::vector<Named> fits;
  io::SvgFigure fig;
  fig.title = c.file;
  if (ext == ".npy" || ext == ".png" || ext == ".pgm") {
    Heightfield hf;
    std::vector<float> profile;
    if (ext == ".npy") {
      io::NpyArray a = io::read_npy(c.file);
      const bool one_d = a.shape.size() == 1 || (a.shape.size() == 2 && (a.shape[0] == 1 || a.shape[1] == 1));
      if (one_d) profile = std::move(a.values);
      else hf = io::read_heightfield(c.file);
    } else {
      hf = io::read_heightfield(c.file);
      if (hf.height() == 1 || hf.width() == 1) profile.assign(hf.data(), hf.data() + hf.size());
    }
    if (!profile.empty()) {
      report["kind"] = "profile";
      report["samples"] = profile.size();
      report.update(hurst_report(profile.data(), profile.size(), nullptr, c, fits));
    } else {
      report["kind"] = "heightfield";
      report["width"] = hf.width(), report["height"] = hf.height();
      report.update(hurst_report(nullptr, 0, &hf, c, fits));
      analysis::BoxCountResult coast;
      report["coastline"] = coastline_report(hf, &coast);
      if (c.drainage) {
        settle_world_size(hf, 0, c.file);
        report["drainage"] = drainage_report(hf, c.periodic);
      }
      if (c.rivers) {
        settle_world_size(hf, 0, c.file);
        ft_hydrology_params p = c.network;
        p.periodic = c.periodic;
        const hydrology::NetworkMeasures m = hydrology::measure_network(hydrology::extract_rivers(hf, hydrology::from_c(p)));
        json j = network_json(m);
        j["min_area"] = p.min_area;
        j["note"] = "real networks: bifurcation ratio R_b about 3-5, length ratio R_l about 1.5-3.5 (Horton 1945, "
                    "Strahler 1957), Hack h about 0.5-0.6; lengths in world units";
        report["rivers"] = j;
      }
      if (!coast.sizes.empty())
        fig.panels.push_back(box_panel("median coastline: box counting", coast.sizes, coast.counts, coast.dimension,
                                       coast.std_error));
    }
    std::vector<io::SvgPanel> panels;
    for (const Named& n : fits) panels.push_back(estimate_panel(n));
    fig.panels.insert(fig.panels.begin(), panels.begin(), panels.end());
  } else if (ext == ".csv" || ext == ".json") {
    // Curves have a dimension, not a Hurst exponent of their own; for a
    // coastline-like curve (a level set of an fBm surface) H = 2 - D.
    const PolylineSet set = io::read_polylines(c.file);
    report["kind"] = "polylines";
    report.update(analysis::polyline_report(set));
    const json& b = report["box_counting"];
    if (b.contains("dimension") && b["dimension"].is_number()) {
      const double d = b["dimension"].get<double>();
      report["dimension"] = d, report["hurst"] = 2 - d;
      fig.panels.push_back(box_panel("box counting", b["sizes"].get<std::vector<double>>(),
                                     b["counts"].get<std::vector<int64_t>>(), d, b["std_error"].get<double>()));
    } else {
      report["dimension"] = nullptr, report["hurst"] = nullptr;
    }
    report["recommended"] = "box_counting";
    report["note"] = "hurst = 2 - dimension, the relation of a coastline to its surface (seed 001)";
  } else {
    fail(FT_ERR_FORMAT, "'" + c.file + "': unsupported input (use .npy, .png or .pgm heightfields/profiles, or "
                        ".csv / .json polylines)");
  }
  if (!c.plot.empty()) {
    if (fig.panels.empty()) invalid("--plot: no estimate succeeded on this input, nothing to draw");
    fig.columns = fig.panels.size() > 4 ? 3 : 2;
    write_plot(c.plot, fig);
  }
  std::printf("%s\n", report.dump(2).c_str());
  return 0;
}

Registration reg({"analyze",
                  "Measure H and the fractal dimension of a heightfield, profile or polylines (JSON report)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto c = std::make_shared<AnalyzeCli>();
                    app.add_option("file", c->file,
                                   "heightfield .npy/.png/.pgm (a 1D .npy or one-row image is a profile), or "
                                   "polylines .csv/.json")
                        ->required();
                    app.add_option("--method", c->method,
                                   "estimate reported as top-level hurst/dimension: auto (variogram_aligned on "
                                   "2^n + 1 grids, else spectral from 256 samples, else variogram), variogram, madogram, variogram_aligned, "
                                   "madogram_aligned, spectral, transect_median")
                        ->capture_default_str();
                    add_param_flags(app, analysis::hurst_param_table(), &c->params, {"method", "transects"});
                    app.add_option("--plot", c->plot, "also draw the log-log fits to this .svg (or .png, through rsvg-convert)");
                    app.add_flag("--drainage", c->drainage,
                                 "heightfields: also report drainage statistics (Hack's h, slope-area theta)");
                    app.add_flag("--periodic", c->periodic,
                                 "--drainage, --rivers: the terrain tiles (route it as a torus)");
                    app.add_flag("--rivers", c->rivers,
                                 "heightfields: also report the river network (fracterra rivers): Strahler orders, "
                                 "Horton's bifurcation and length ratios, total length, drainage density, Hack's h");
                    app.add_option("--min-area", c->network.min_area,
                                   "--rivers: drainage area at a channel head, world units^2 (as rivers --min-area)")
                        ->capture_default_str();
                    return [c] {
                      // Every estimator runs, so every band field is checked (as FT_HURST_AUTO reads them all).
                      c->params.method = FT_HURST_AUTO;
                      check_ranges(analysis::hurst_param_table(), &c->params);
                      c->band.lag_min = c->params.lag_min, c->band.lag_max = c->params.lag_max;
                      c->band.freq_min = c->params.freq_min, c->band.freq_max = c->params.freq_max;
                      return run(*c);
                    };
                  },
                  40});

}  // namespace
}  // namespace ft::cli::cmd_analyze
