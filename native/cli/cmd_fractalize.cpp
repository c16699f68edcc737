// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra fractalize: refine an OBJ mesh with OpenSubdiv and displace it
// fractally (Voss midpoint displacement or Feder's additions), write OBJ and
// optionally a POV-Ray mesh2 include.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "io/obj_io.hpp"
#include "povray/mesh2_export.hpp"
#include "subdiv/fractalize.hpp"
#include "subdiv/fractalize_params.hpp"

namespace ft::cli::cmd_fractalize {
namespace {

struct FractalizeOptions {
  ft_fractalize_params p = subdiv::default_fractalize_params();
  std::string in, out, pov, pov_name = "FT_Fractal";
  bool stats = false;
};

int run(const FractalizeOptions& o) {
  const Mesh base = io::read_obj(o.in);
  Stopwatch clock;
  Mesh mesh;
  try {
    mesh = subdiv::fractalize(base, o.p);
  } catch (const Error& e) {
    if (e.status() != FT_ERR_INVALID_ARGUMENT) throw;
    // The library counts faces and vertices from 0, OBJ 'f' lines from 1.
    throw Error(e.status(), std::string(e.what()) + " (in '" + o.in +
                                "'; faces and vertices are numbered from 0 in the order of the file)");
  }
  const double seconds = clock.seconds();
  char comment[256];
  std::snprintf(comment, sizeof comment, "fractalize levels=%d hurst=%g sigma=%g seed=%llu scheme=%d mode=%d",
                o.p.levels, o.p.hurst, o.p.sigma, (unsigned long long)o.p.seed, o.p.scheme, o.p.mode);
  if (!o.out.empty()) io::write_obj(mesh, o.out, std::string(comment) + " from " + o.in);
  if (!o.pov.empty()) pov::write_mesh2(mesh, o.pov, o.pov_name);
  if (o.stats) {
    nlohmann::json j = {{"seconds", seconds},
                        {"base_vertices", base.vertex_count()},
                        {"base_faces", base.face_count()},
                        {"vertices", mesh.vertex_count()},
                        {"faces", mesh.face_count()}};
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"fractalize", "Fractalize a polygon mesh (OBJ) with OpenSubdiv and midpoint displacement",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<FractalizeOptions>();
                    auto& p = o->p;
                    app.add_option("--in", o->in, "input mesh .obj (polygons; 't crease'/'t corner' tags honoured)")
                        ->required()->check(existing_file);
                    // --levels .. --threads, --scheme midpoint|additions: from the table.
                    add_param_flags(app, subdiv::fractalize_param_table(), &p);
                    app.add_option("--out", o->out, "output .obj (written atomically)");
                    app.add_option("--pov", o->pov, "also write a POV-Ray include declaring a mesh2 with normals");
                    app.add_option("--pov-name", o->pov_name, "identifier declared in the --pov file")
                        ->capture_default_str();
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, vertex and face counts");
                    return [o] {
                      if (o->out.empty() && o->pov.empty() && !o->stats) invalid("give --out FILE, --pov FILE and/or --stats");
                      return run(*o);
                    };
                  },
                  40});

}  // namespace
}  // namespace ft::cli::cmd_fractalize
