// fracterra analyze: measure H and D of a heightfield, a profile or a set of
// polylines, print a JSON report, and optionally plot the log-log fits.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/hurst.hpp"
#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/npy.hpp"

namespace ft::cli {
namespace {

using nlohmann::json;

struct AnalyzeCli {
  std::string file, plot, method = "auto";
  HurstOptions band;  // only the band fields are used
  bool json_flag = false;
};

const std::vector<HurstMethod> kAllMethods = {HurstMethod::kVariogramAligned, HurstMethod::kVariogram,
                                              HurstMethod::kMadogramAligned, HurstMethod::kMadogram,
                                              HurstMethod::kSpectral};

// One estimate, for the report and the plot.
struct Named {
  std::string name;
  HurstEstimate e;
};

json estimate_json(const HurstEstimate& e) {
  json j = {{"hurst", e.hurst},
            {"dimension", e.dimension},
            {"stderr", e.stderr_hurst},
            {"band", {{"unit", hurst_method_uses_lags(e.method) ? "lag (samples)" : "frequency (cycles per record)"},
                      {"lo", e.band_lo},
                      {"hi", e.band_hi}}},
            {"points", e.fit.points},
            {"slope", e.fit.slope},
            {"intercept", e.fit.intercept}};
  if (e.transects) j["transects"] = e.transect_count;
  return j;
}

bool dyadic(int64_t n) { return n >= 3 && ((n - 1) & (n - 2)) == 0; }

// Every estimator on a profile (surface = nullptr) or a surface. A method
// that cannot run on this input (band too narrow, ...) reports its error.
json hurst_report(const float* profile, size_t n, const Heightfield* surface, const AnalyzeCli& c,
                  std::vector<Named>& fits) {
  json methods = json::object();
  auto run = [&](const std::string& name, HurstOptions o) {
    try {
      HurstEstimate e = surface ? estimate_hurst_surface(*surface, o) : estimate_hurst_profile(profile, n, o);
      methods[name] = estimate_json(e);
      fits.push_back({name, std::move(e)});
    } catch (const Error& err) {
      methods[name] = {{"error", err.what()}};
    }
  };
  for (HurstMethod m : kAllMethods) {
    HurstOptions o = c.band;
    o.method = m;
    run(hurst_method_name(m), o);
  }
  if (surface) {
    HurstOptions o = c.band;
    o.method = HurstMethod::kVariogram;
    o.transects = true;
    run("transect_median", o);
  }
  // The recommendation: the dyadic-aligned variogram on 2^n + 1 grids (exact
  // for the midpoint and additions generators, which build those grids),
  // else the plain variogram (all pairs: the most data for a stationary field).
  const bool grid = surface ? dyadic(surface->width()) && dyadic(surface->height()) : dyadic(int64_t(n));
  std::string pick = c.method != "auto" ? c.method : grid ? "variogram_aligned" : "variogram";
  if (!methods.contains(pick)) invalid("--method '" + pick + "' is not one of the estimators run on this input");
  json report;
  if (methods[pick].contains("error")) {
    report["hurst"] = nullptr, report["dimension"] = nullptr;
  } else {
    report["hurst"] = methods[pick]["hurst"], report["dimension"] = methods[pick]["dimension"];
  }
  report["recommended"] = pick;
  report["methods"] = methods;
  return report;
}

int run(const AnalyzeCli& c) {
  const std::string ext = extension_of(c.file);
  json report = {{"file", c.file}};
  std::vector<Named> fits;
  if (ext == ".npy" || ext == ".png" || ext == ".pgm") {
    Heightfield hf;
    std::vector<float> profile;
    if (ext == ".npy") {
      NpyArray a = read_npy(c.file);
      const bool one_d = a.shape.size() == 1 || (a.shape.size() == 2 && (a.shape[0] == 1 || a.shape[1] == 1));
      if (one_d) profile = std::move(a.values);
      else hf = read_heightfield(c.file);
    } else {
      hf = read_heightfield(c.file);
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
    }
  } else {
    fail(FT_ERR_FORMAT, "'" + c.file + "': unsupported input (use .npy, .png or .pgm heightfields/profiles, or "
                        ".csv / .json polylines)");
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
                                   "2^n + 1 grids, else variogram), variogram, madogram, variogram_aligned, "
                                   "madogram_aligned, spectral, transect_median")
                        ->capture_default_str();
                    app.add_option("--lag-min", c->band.lag_min, "smallest lag in samples (0 = 1)")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--lag-max", c->band.lag_max, "largest lag in samples (0 = max(2, (n - 1) / 16))")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--freq-min", c->band.freq_min,
                                   "spectral: lowest frequency, cycles per record (0 = clamp(n / 128, 1, 8))")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--freq-max", c->band.freq_max,
                                   "spectral: highest frequency, cycles per record (0 = n / 8)")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--plot", c->plot, "also draw the log-log fits to this .svg");
                    app.add_flag("--json", c->json_flag, "accepted for compatibility: the report is always JSON");
                    return [c] { return run(*c); };
                  },
                  40});

}  // namespace
}  // namespace ft::cli
