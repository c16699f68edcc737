// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra study fpl: the ensemble experiment of seed 003 (Nikulin): means
// of eta, chi, gamma and the dimensions over K lines per (s, r), written as
// CSV and plotted against the paper's fitted formulas.
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/svg_plot.hpp"
#include "polyline/fpl_study.hpp"

namespace ft::cli::cmd_study {
namespace {

const std::map<std::string, int> kRngs = {{"uniform", 0}, {"normal", 1}};

struct StudyOptions {
  int rng = 0;
  std::string spreads = "0.05,0.1,0.15,0.2,0.25,0.3,0.35,0.4,0.45,0.5";
  std::string depths = "8";
  int count = 100;
  uint64_t seed = 1;
  std::string out_csv, plot;
  bool no_box = false;
};

template <class T>
std::vector<T> parse_list(const std::string& text, const char* what) {
  std::vector<T> v;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0') invalid(std::string(what) + ": '" + item + "' is not a number");
    if constexpr (std::is_integral_v<T>) {
      if (x != std::floor(x)) invalid(std::string(what) + ": '" + item + "' is not an integer");
    }
    v.push_back(T(x));
  }
  if (v.empty()) invalid(std::string(what) + " is empty");
  return v;
}

std::string csv(const std::vector<polyline::FplStudyRow>& rows, const char* rng) {
  std::string o =
      "rng,spread,depth,count,eta_mean,eta_se,chi_mean,chi_se,gamma_mean,gamma_se,mass_dim_mean,mass_dim_se,"
      "box_dim_mean,box_dim_se,paper_eta,paper_chi,paper_gamma,paper_dim\n";
  char buf[512];
  for (const polyline::FplStudyRow& r : rows) {
    std::snprintf(buf, sizeof buf, "%s,%g,%d,%d,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g,%.6g,%.6g,%.6g\n",
                  rng, r.spread, r.depth, r.count, r.eta.mean, r.eta.se, r.chi.mean, r.chi.se, r.gamma.mean,
                  r.gamma.se, r.mass_dimension.mean, r.mass_dimension.se, r.box_dimension.mean, r.box_dimension.se,
                  r.paper_eta, r.paper_chi, r.paper_gamma, r.paper_dimension);
    o += buf;
  }
  return o;
}

io::SvgPanel panel(const std::string& title, const std::string& x_label, const std::string& y_label) {
  io::SvgPanel p;
  p.title = title, p.x_label = x_label, p.y_label = y_label;
  return p;
}

// Measured means: points; fits: dashed lines.
io::SvgSeries points(const std::string& label, const std::string& color) {
  io::SvgSeries s;
  s.label = label, s.color = color, s.line = false, s.points = true;
  return s;
}
io::SvgSeries dashed(const std::string& label, const std::string& color, std::vector<double> x = {},
                 std::vector<double> y = {}) {
  io::SvgSeries s;
  s.label = label, s.color = color, s.dashed = true, s.width = 1.2, s.x = std::move(x), s.y = std::move(y);
  return s;
}

std::string fmt_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Panels: eta/s, chi/s, gamma against s (one series per r), gamma against r
// and the dimension against r (one series per s); our means as points with
// +-2 standard-error bars, the paper's formulas dashed in the same colour.
io::SvgFigure plot(const std::vector<polyline::FplStudyRow>& rows, const std::vector<double>& spreads, const std::vector<int>& depths,
               polyline::FplRng rng) {
  const polyline::PaperFit fit = polyline::paper_fit(rng);
  const bool uniform = rng == polyline::FplRng::kUniform;
  const std::string sname = uniform ? "s" : "sigma";
  auto row_at = [&](double s, int r) -> const polyline::FplStudyRow& {
    for (const polyline::FplStudyRow& x : rows)
      if (x.spread == s && x.depth == r) return x;
    return rows.front();
  };
  io::SvgFigure f;
  f.title = std::string("FPL ensemble study (seed 003), ") + (uniform ? "uniform urf(s)" : "normal nrf(sigma)") +
            ", K = " + std::to_string(rows.front().count) + " lines per point; dashed: the paper's fits";
  f.columns = 3;
  const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  io::SvgPanel eta = panel("eta / " + sname + " (max deviation)", sname, "eta / " + sname);
  io::SvgPanel chi = panel("chi / " + sname + " (mean deviation)", sname, "chi / " + sname);
  io::SvgPanel gam = panel("gamma (elongation) vs " + sname, sname, "gamma");
  gam.log_y = true;
  for (size_t d = 0; d < depths.size(); ++d) {
    const int r = depths[d];
    const std::string label = "r = " + std::to_string(r);
    io::SvgSeries e = points(label, colors[d % 8]), c = e, g = e;
    for (double s : spreads) {
      if (!(s > 0)) continue;
      const polyline::FplStudyRow& x = row_at(s, r);
      e.x.push_back(s), e.y.push_back(x.eta.mean / s), e.y_error.push_back(2 * x.eta.se / s);
      c.x.push_back(s), c.y.push_back(x.chi.mean / s), c.y_error.push_back(2 * x.chi.se / s);
      g.x.push_back(s), g.y.push_back(x.gamma.mean), g.y_error.push_back(2 * x.gamma.se);
    }
    io::SvgSeries gp = dashed("", colors[d % 8]);
    for (int i = 0; i <= 100; ++i) {
      const double s = spreads.back() * i / 100.0;
      gp.x.push_back(s), gp.y.push_back(std::exp2(fit.alpha * std::pow(s, fit.beta) * r));
    }
    eta.series.push_back(e), chi.series.push_back(c), gam.series.push_back(g), gam.series.push_back(gp);
  }
  const double smax = spreads.back();
  eta.series.push_back(dashed("paper " + fmt_g(fit.eta_per_s), "#000", {0, smax}, {fit.eta_per_s, fit.eta_per_s}));
  chi.series.push_back(dashed("paper " + fmt_g(fit.chi_per_s), "#000", {0, smax}, {fit.chi_per_s, fit.chi_per_s}));
  eta.y_min = chi.y_min = 0;
  eta.y_max = 2 * fit.eta_per_s, chi.y_max = 2 * fit.chi_per_s;
  io::SvgPanel gr = panel("gamma vs r: 2^(" + fmt_g(fit.alpha) + " " + sname + "^" + fmt_g(fit.beta) + " r)", "depth r", "gamma");
  gr.log_y = true;
  io::SvgPanel dim = panel("mass dimension vs r: eq. 6 dashed", "depth r", "D");
  io::SvgPanel dims = panel("dimension vs " + sname + " (r = " + std::to_string(depths.back()) + ")", sname, "D");
  size_t k = 0;
  io::SvgSeries mass_s = points("mass (eq. 4g)", "#1f77b4"), box_s = points("box counting", "#d62728");
  io::SvgSeries eq6 = dashed("eq. 6", "#000");
  for (double s : spreads) {
    if (!(s > 0)) continue;
    const polyline::FplStudyRow& last = row_at(s, depths.back());
    mass_s.x.push_back(s), mass_s.y.push_back(last.mass_dimension.mean), mass_s.y_error.push_back(2 * last.mass_dimension.se);
    box_s.x.push_back(s), box_s.y.push_back(last.box_dimension.mean), box_s.y_error.push_back(2 * last.box_dimension.se);
    if (depths.size() < 2) continue;
    const std::string col = colors[k++ % 8];
    io::SvgSeries g = points(sname + " = " + fmt_g(s), col), gp = dashed("", col), d = g, dp = gp;
    for (int r : depths) {
      const polyline::FplStudyRow& x = row_at(s, r);
      g.x.push_back(r), g.y.push_back(x.gamma.mean), g.y_error.push_back(2 * x.gamma.se);
      gp.x.push_back(r), gp.y.push_back(x.paper_gamma);
      d.x.push_back(r), d.y.push_back(x.mass_dimension.mean), d.y_error.push_back(2 * x.mass_dimension.se);
      dp.x.push_back(r), dp.y.push_back(x.paper_dimension);
    }
    gr.series.push_back(g), gr.series.push_back(gp), dim.series.push_back(d), dim.series.push_back(dp);
  }
  for (int i = 0; i <= 100; ++i) {
    const double s = smax * i / 100.0, a = fit.alpha * std::pow(s, fit.beta);
    eq6.x.push_back(s), eq6.y.push_back(a < 1 ? 1 / (1 - a) : NAN);
  }
  dims.series = {mass_s, box_s, eq6};
  f.panels = {eta, chi, gam, dims};
  if (depths.size() >= 2) f.panels.push_back(gr), f.panels.push_back(dim);
  return f;
}

int run(const StudyOptions& o) {
  polyline::FplStudyConfig c;
  c.rng = o.rng == 1 ? polyline::FplRng::kNormal : polyline::FplRng::kUniform;
  c.spreads = parse_list<double>(o.spreads, "--spread");
  c.depths = parse_list<int>(o.depths, "--depth");
  std::sort(c.spreads.begin(), c.spreads.end());
  std::sort(c.depths.begin(), c.depths.end());
  c.count = o.count;
  c.seed = o.seed;
  c.box_counting = !o.no_box;
  Stopwatch clock;
  const std::vector<polyline::FplStudyRow> rows = polyline::run_fpl_study(c);
  const std::string table = csv(rows, o.rng == 1 ? "normal" : "uniform");
  if (!o.out_csv.empty()) io::write_file_atomically(o.out_csv, table);
  else std::fputs(table.c_str(), stdout);
  if (!o.plot.empty()) io::write_svg(o.plot, plot(rows, c.spreads, c.depths, c.rng));
  std::fprintf(stderr, "study: %zu points x %d lines in %.2f s\n", rows.size(), c.count, clock.seconds());
  return 0;
}

Registration reg({"study", "Reproduce a paper's experiment: 'study fpl' (seed 003 ensemble statistics)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<StudyOptions>();
                    app.require_subcommand(1);
                    CLI::App* fpl = app.add_subcommand("fpl", "FPL ensemble: eta, chi, gamma and dimensions vs s and r");
                    fpl->add_option("--rng", o->rng, "uniform urf(s) or normal nrf(sigma)")
                        ->transform(choice(kRngs))->capture_default_str();
                    fpl->add_option("--spread", o->spreads, "comma-separated spreads s (or sigma), each >= 0")
                        ->capture_default_str();
                    fpl->add_option("--depth", o->depths, "comma-separated depths r, each 1..20")->capture_default_str();
                    fpl->add_option("--count", o->count, "lines K per (s, r), 2..100000")->capture_default_str();
                    fpl->add_option("--seed", o->seed, "line k uses seed + k")->capture_default_str();
                    fpl->add_option("--out-csv", o->out_csv, "write the table here (default: standard output)");
                    fpl->add_option("--plot", o->plot, "write an SVG plot here");
                    fpl->add_flag("--no-box", o->no_box, "skip box counting (faster)");
                    return [o] { return run(*o); };
                  },
                  60});

}  // namespace
}  // namespace ft::cli::cmd_study
