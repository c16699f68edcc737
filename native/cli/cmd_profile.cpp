// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra profile: a Voss 1D midpoint-displacement profile as CSV/NPY.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/buffer.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/npy.hpp"
#include "io/polyline_io.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::cli::cmd_profile {
namespace {

struct ProfileOptions {
  ft_profile_params p = terrain::default_profile_params();
  std::string reference, out;
  bool stats = false;
};

std::vector<float> read_reference(const std::string& path) {
  if (io::extension_of(path) == ".npy") {
    io::NpyArray a = io::read_npy(path);
    if (a.shape.size() != 1) invalid("the reference '" + path + "' must be a 1D array");
    return a.values;
  }
  // A CSV polyline: its y values are the reference heights.
  PolylineSet s = io::read_polylines(path);
  std::vector<float> v;
  for (const Vec3& q : s.points) v.push_back(float(q[1]));
  return v;
}

int run(const ProfileOptions& o) {
  ft_profile_params p = o.p;
  std::vector<float> ref;
  if (!o.reference.empty()) {
    ref = read_reference(o.reference);
    p.reference = ref.data();
    p.reference_size = int32_t(ref.size());
  }
  terrain::validate_profile_params(p);
  const size_t n = (size_t(1) << p.levels) + 1;
  // The samples, plus a polyline copy (xyz + radius, 32 bytes a vertex) for
  // .csv/.json: refused up front, with the size, when above the memory cap.
  const std::string ext = io::extension_of(o.out);
  const bool as_polyline = ext == ".csv" || ext == ".json";
  check_allocation(checked_bytes(n, sizeof(float) + (as_polyline ? sizeof(Vec3) + sizeof(double) : 0)),
                   "a profile of levels " + std::to_string(p.levels) + " (" + std::to_string(n) + " samples)");
  std::vector<float> x(n);
  Stopwatch clock;
  terrain::generate_profile(p, x.data(), n);
  const double seconds = clock.seconds();
  if (!o.out.empty()) {
    if (ext == ".npy") {
      io::write_npy(o.out, {int64_t(n)}, x.data());
    } else if (as_polyline) {
      // As a polyline on t in [0, 1]: x = t, y = X(t).
      PolylineSet s;
      for (size_t i = 0; i < n; ++i) s.add({double(i) / double(n - 1), double(x[i]), 0.0});
      s.end_line();
      io::write_polylines(s, o.out);
    } else {
      invalid("'" + o.out + "': unsupported profile format (use .csv, .json or .npy)");
    }
  }
  if (o.stats) {
    double lo = x[0], hi = x[0], sum = 0;
    for (float v : x) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v), sum += v;
    nlohmann::json j = {{"seconds", seconds}, {"samples", n}, {"min", lo}, {"max", hi}, {"mean", sum / double(n)}};
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"profile", "Generate a Voss 1D fractal profile (a horizon)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<ProfileOptions>();
                    auto& p = o->p;
                    add_param_flags(app, terrain::profile_param_table(), &p);
                    app.add_option("--reference", o->reference,
                                   "2^m + 1 reference values: a 1D .npy, or a .csv whose y column is used")
                        ->check(existing_file);
                    app.add_option("--out", o->out, "output .csv (x = t in [0,1], y = height), .json or .npy");
                    app.add_flag("--stats", o->stats, "print a JSON object with seconds, min, max, mean");
                    return [o] {
                      if (o->out.empty() && !o->stats) invalid("give --out FILE and/or --stats");
                      return run(*o);
                    };
                  },
                  20});

}  // namespace
}  // namespace ft::cli::cmd_profile
