// SPDX-License-Identifier: GPL-3.0-or-later
// POV-Ray speed, measured with the real povray in one run:
//   1. a polyline of 4097 and 16385 points as chunked sphere_sweeps (32
//      segments per piece) against one sweep, traced at 320 x 240;
//   2. a 1025^2 terrain as height_field (16-bit PNG) against mesh2 (what
//      Blender's POV-Ray exporter writes): file size and parse time.
// Times are POV-Ray's own "Parse Time" / "Trace Time" figures, each the
// median of --repetitions renders (default 3) in this one run.
// Usage: povray_bench [--repetitions N] [folder]   (default: a temporary folder, removed after)
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "io/atomic_file.hpp"
#include "povray/heightfield_export.hpp"
#include "povray/render.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"
#include "terrain/terrain.hpp"

namespace fs = std::filesystem;
using namespace ft;

namespace {

struct Times {
  double parse = 0, trace = 0;
};

int g_repetitions = 3;

Times render_once(const std::string& scene, int w, int h) {
  pov::RenderOptions o;
  o.width = w;
  o.height = h;
  o.antialias = 0;
  const auto r = pov::render_scene(scene, scene + ".png", o);
  Times t;
  std::regex re("(Parse|Trace) Time:.*\\(([0-9.]+) seconds\\)");
  for (auto it = std::sregex_iterator(r.messages.begin(), r.messages.end(), re); it != std::sregex_iterator(); ++it)
    ((*it)[1] == "Parse" ? t.parse : t.trace) = std::stod((*it)[2]);
  return t;
}

// The median parse and trace times of g_repetitions renders.
Times render(const std::string& scene, int w, int h) {
  std::vector<double> parse, trace;
  for (int i = 0; i < g_repetitions; ++i) {
    const Times t = render_once(scene, w, h);
    parse.push_back(t.parse), trace.push_back(t.trace);
  }
  auto median = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  return {median(parse), median(trace)};
}

// A fractal-looking polyline across the unit square: orthogonal midpoint
// displacement (uniform spread 0.15) with Philox numbers, 2^levels + 1 points.
PolylineSet fpl(int levels, uint64_t seed) {
  const size_t n = (size_t(1) << levels) + 1;
  std::vector<Vec3> p(n);
  p[0] = {0, 0.5, 0};
  p[n - 1] = {1, 0.5, 0};
  uint32_t level = 0;
  for (size_t step = n - 1; step > 1; step /= 2, ++level) {
    std::vector<float> u(n / step + 1);
    uniform_fill(seed, Counter{0, level, Stream::kPolyline}, 0, u.size(), u.data());
    for (size_t i = 0; i + step < n; i += step) {
      const Vec3 &a = p[i], &b = p[i + step];
      const double f = 0.15 * (2 * u[i / step] - 1);
      p[i + step / 2] = {(a[0] + b[0]) / 2 - f * (b[1] - a[1]), (a[1] + b[1]) / 2 + f * (b[0] - a[0]), 0};
    }
  }
  PolylineSet s;
  for (const Vec3& q : p) s.add(q, 0.002);
  s.end_line();
  return s;
}

const char* kHeader =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
    "camera { location <0.5, 1.1, 0.5> look_at <0.5, 0, 0.5> angle 60 right x*image_width/image_height }\n"
    "light_source { <-3, 10, -5> rgb 1 }\nbackground { rgb 0.2 }\n";

std::string mesh2(const Heightfield& hf, const pov::TerrainPlacement& pl) {
  // What Blender's exporter writes for a grid: every vertex and triangle.
  std::string s = "mesh2 {\n vertex_vectors { " + std::to_string(hf.size()) + ",\n";
  char buf[160];
  for (int y = 0; y < hf.height(); ++y)
    for (int x = 0; x < hf.width(); ++x) {
      std::snprintf(buf, sizeof buf, "  <%.6f, %.6f, %.6f>,\n", x * pl.world_size_x / (hf.width() - 1),
                    hf.at(x, y) * pl.vertical_scale, y * pl.world_size_y / (hf.height() - 1));
      s += buf;
    }
  const int64_t faces = int64_t(hf.width() - 1) * (hf.height() - 1) * 2;
  s += " }\n face_indices { " + std::to_string(faces) + ",\n";
  for (int y = 0; y + 1 < hf.height(); ++y)
    for (int x = 0; x + 1 < hf.width(); ++x) {
      const long long a = (long long)y * hf.width() + x, b = a + 1, c = a + hf.width(), d = c + 1;
      std::snprintf(buf, sizeof buf, "  <%lld, %lld, %lld>, <%lld, %lld, %lld>,\n", a, b, d, a, d, c);
      s += buf;
    }
  return s + " }\n pigment { rgb 1 }\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string folder;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--repetitions=", 0) == 0) g_repetitions = std::max(1, std::atoi(a.c_str() + 14));
    else if (a == "--repetitions" && i + 1 < argc) g_repetitions = std::max(1, std::atoi(argv[++i]));
    else if (a.rfind("--benchmark_repetitions=", 0) == 0) g_repetitions = std::max(1, std::atoi(a.c_str() + 24));
    else folder = a;
  }
  const bool temp = folder.empty();
  const fs::path dir =
      temp ? fs::temp_directory_path() / ("ft_povray_bench_" + std::to_string(::getpid())) : fs::path(folder);
  std::printf("median of %d renders each\n", g_repetitions);
  fs::create_directories(dir);
  try {
    std::printf("sphere_sweep: one polyline, radius 0.002, traced at 320x240 (no anti-aliasing)\n");
    std::printf("%8s %14s %14s %10s\n", "points", "chunked 32 s", "one sweep s", "speed-up");
    std::fflush(stdout);
    for (int levels : {12, 14}) {
      const PolylineSet line = fpl(levels, 42);
      double t[2];
      for (int k = 0; k < 2; ++k) {
        pov::SweepOptions o;
        o.segments_per_sweep = k == 0 ? 32 : int64_t(1) << 30;
        const std::string f = (dir / ("sweep_" + std::to_string(levels) + "_" + std::to_string(k) + ".pov")).string();
        io::write_file_atomically(f, kHeader + pov::sweeps_sdl(line, o, "pigment { rgb <1, 0.5, 0.2> }\n"));
        t[k] = render(f, 320, 240).trace;
      }
      std::printf("%8lld %14.3f %14.3f %9.0fx\n", (long long)line.vertex_count(), t[0], t[1],
                  t[1] / std::max(t[0], 1e-3));
      std::fflush(stdout);
    }

    ft_terrain_params p = terrain::default_terrain_params();
    p.levels = 10;
    p.seed = 7;
    const Heightfield hf = terrain::generate_terrain(p);
    const HeightStats st = hf.stats();
    const std::string png = (dir / "hf.png").string();
    const auto pl = pov::write_heightfield_png(hf, png, 1, 1, 0.2 / (st.max - st.min));
    const std::string a = (dir / "hf.pov").string(), b = (dir / "mesh.pov").string();
    io::write_file_atomically(a, kHeader + std::string("#declare T = ") + pov::heightfield_sdl("hf.png", pl, NAN) +
                                 "object { T pigment { rgb 1 } }\n");
    io::write_file_atomically(b, kHeader + mesh2(hf, pl));
    const double sa = double(fs::file_size(a) + fs::file_size(png)), sb = double(fs::file_size(b));
    const Times ta = render(a, 64, 48), tb = render(b, 64, 48);
    std::printf("\nterrain 1025^2: file size and parse time (render 64x48)\n");
    std::printf("%14s %10s %10s\n", "", "size MB", "parse s");
    std::printf("%14s %10.2f %10.3f\n", "height_field", sa / 1e6, ta.parse);
    std::printf("%14s %10.2f %10.3f\n", "mesh2", sb / 1e6, tb.parse);
    std::printf("%14s %9.0fx %9.0fx\n", "ratio", sb / sa, tb.parse / std::max(ta.parse, 1e-3));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "povray_bench: %s\n", e.what());
    if (temp) fs::remove_all(dir);
    return 1;
  }
  if (temp) fs::remove_all(dir);
  return 0;
}
