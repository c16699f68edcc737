// fracterra fractalize: refine an OBJ mesh with OpenSubdiv and displace it
// fractally (Voss midpoint displacement or Feder's additions), write OBJ and
// optionally a POV-Ray mesh2 include.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "io/obj_io.hpp"
#include "povray/mesh2_export.hpp"
#include "subdiv/fractalize.hpp"

namespace ft::cli {
namespace {

const std::map<std::string, int> kSchemes = {
    {"catmark", FT_SCHEME_CATMARK}, {"loop", FT_SCHEME_LOOP}, {"bilinear", FT_SCHEME_BILINEAR}};
const std::map<std::string, int> kModes = {{"voss", FT_FRACTALIZE_MIDPOINT}, {"additions", FT_FRACTALIZE_ADDITIONS}};

struct FractalizeOptions {
  ft_fractalize_params p = default_fractalize_params();
  std::string in, out, pov, pov_name = "FT_Fractal";
  bool stats = false;
};

int run(const FractalizeOptions& o) {
  const Mesh base = read_obj(o.in);
  Stopwatch clock;
  Mesh mesh;
  try {
    mesh = fractalize(base, o.p);
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
  if (!o.out.empty()) write_obj(mesh, o.out, std::string(comment) + " from " + o.in);
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
                        ->required()->check(CLI::ExistingFile);
                    app.add_option("--levels", p.levels, "refinement steps L (faces grow 4^L), 1..10")
                        ->check(CLI::Range(1, kMaxSubdivLevels))->capture_default_str();
                    app.add_option("--hurst", p.hurst, "Hurst exponent H, 0..1: level k moves by sigma 2^(-kH)")
                        ->check(CLI::Range(0.0, 1.0))->capture_default_str();
                    app.add_option("--sigma", p.sigma, "displacement scale in mesh units (>= 0; 0 = plain subdivision)")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--seed", p.seed, "random seed (64-bit)")->capture_default_str();
                    app.add_option("--scheme", p.scheme, "subdivision scheme: catmark (any polygons), loop (triangles "
                                                         "only), bilinear")
                        ->transform(choice(kSchemes))->capture_default_str();
                    app.add_option("--mode", p.mode, "voss: only new vertices move; additions: all vertices move")
                        ->transform(choice(kModes))->capture_default_str();
                    app.add_flag("--fix-boundary", p.fix_boundary, "vertices on open boundaries never move (default off)");
                    app.add_flag("--scale-by-edge-length", p.scale_by_edge_length,
                                 "sigma is a fraction of the local base edge length (default off)");
                    app.add_option("--threads", p.threads, "worker threads, 0 = all cores (output never depends on it)")
                        ->check(CLI::Range(0, 1024))->capture_default_str();
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
}  // namespace ft::cli
