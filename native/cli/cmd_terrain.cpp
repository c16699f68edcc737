// fracterra terrain: generate a heightfield and write it as PNG/PGM/NPY.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "contour/marching_squares.hpp"
#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"
#include "io/polyline_io.hpp"
#include "povray/scene.hpp"
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain.hpp"

namespace ft::cli {
namespace {

const std::map<std::string, int> kMethods = {
    {"midpoint", FT_TERRAIN_MIDPOINT}, {"additions", FT_TERRAIN_ADDITIONS}, {"fbm", FT_TERRAIN_FBM},
    {"spectral", FT_TERRAIN_SPECTRAL}, {"interpolated", FT_TERRAIN_INTERPOLATED},
    {"mandelbrot", FT_TERRAIN_MANDELBROT}};
const std::map<std::string, int> kBases = {
    {"value", FT_BASIS_VALUE}, {"gradient", FT_BASIS_GRADIENT}, {"simplex", FT_BASIS_SIMPLEX},
    {"cellular", FT_BASIS_CELLULAR_F1}, {"cellular-f2f1", FT_BASIS_CELLULAR_F2F1}};
const std::map<std::string, int> kVariants = {
    {"standard", FT_FBM_STANDARD}, {"ridged", FT_FBM_RIDGED}, {"hybrid", FT_FBM_HYBRID}, {"hetero", FT_FBM_HETERO}};

// The name of an enum value, for --help defaults ("midpoint", not "0").
std::string name_of(const std::map<std::string, int>& names, int value) {
  for (const auto& [name, v] : names)
    if (v == value) return name;
  return std::to_string(value);
}

// "--size N" (square) or "--size WxH".
void parse_size(const std::string& text, ft_terrain_params& p) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  const int got = std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra);
  if (got == 1) h = w;
  else if (!(got == 3 && (x == 'x' || x == 'X')))
    invalid("--size must be N or WxH (e.g. 1024 or 2048x1024), got '" + text + "'");
  p.width = w;
  p.height = h;
}
// "--center X,Y" (the Mandelbrot view's centre in the complex plane).
void parse_center(const std::string& text, ft_terrain_params& p) {
  double x = 0, y = 0;
  char comma = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lf%c%lf%c", &x, &comma, &y, &extra) != 3 || comma != ',')
    invalid("--center must be X,Y (e.g. -0.745,0.11), got '" + text + "'");
  p.center_x = x;
  p.center_y = y;
}

const std::map<std::string, int> kRefScales = {
    {"sigma", FT_REFSCALE_SIGMA}, {"mean", FT_REFSCALE_MEAN}, {"std", FT_REFSCALE_STD}};

struct TerrainOptions {
  ft_terrain_params p = default_terrain_params();
  std::string reference, out, size, pov, center, curves_out, erode;
  std::vector<double> curves;
  bool stats = false, curves_world = false;
};

// The Mandelbrot terrain's curves of equal escape time: the contours at the
// heights those escape times map to, in columns and rows or world units.
void write_escape_curves(const TerrainOptions& o, const ft_terrain_params& p, const Heightfield& hf) {
  std::vector<double> levels;
  for (double nu : o.curves) levels.push_back(mandelbrot_height(nu, p.sigma));
  PolylineSet set = marching_squares(hf, levels);
  if (o.curves_world) {
    const double k = hf.world_size() / double(hf.width() - 1);
    for (Vec3& v : set.points) v[0] *= k, v[1] *= k;
  }
  write_polylines(set, o.curves_out);
}

int run(const TerrainOptions& o) {
  ft_terrain_params p = o.p;
  if (!o.size.empty()) parse_size(o.size, p);
  if (!o.center.empty()) parse_center(o.center, p);
  if (!o.curves.empty() || !o.curves_out.empty()) {
    // Refused before the work, not after it.
    if (p.method != FT_TERRAIN_MANDELBROT) invalid("--curves: curves of equal escape time need --method mandelbrot");
    if (o.curves.empty() || o.curves_out.empty()) invalid("give both --curves LIST and --curves-out FILE");
    for (double nu : o.curves) check_finite("--curves value", nu);
  }
  Heightfield reference;
  if (!o.reference.empty()) {
    reference = read_heightfield(o.reference);
    if (reference.width() != reference.height())
      invalid("the reference grid '" + o.reference + "' is " + std::to_string(reference.width()) + " x " +
              std::to_string(reference.height()) + "; it must be square, 2^m + 1 per side");
    p.reference = reference.data();
    p.reference_size = reference.width();
  }
  Stopwatch clock;
  Heightfield hf = generate_terrain(p);
  if (!o.erode.empty()) {
    erosion::ErosionConfig e = erosion::erosion_preset(o.erode);
    // Spectral terrains tile with period W x H (the FFT grid); the others'
    // periodic grids repeat their first row and column, which a torus of
    // W x H would not keep equal, so they erode bounded.
    e.periodic = p.method == FT_TERRAIN_SPECTRAL;
    e.threads = p.threads;
    hf = erosion::erode(hf, e, nullptr);
  }
  const double seconds = clock.seconds();
  if (!o.out.empty()) write_heightfield(hf, o.out);
  if (!o.pov.empty()) pov::write_terrain_scene(hf, o.pov);  // PNG beside it
  if (!o.curves_out.empty()) write_escape_curves(o, p, hf);
  if (o.stats) {
    const HeightStats s = hf.stats();
    nlohmann::json j = {{"seconds", seconds}, {"width", hf.width()}, {"height", hf.height()},
                        {"min", s.min},       {"max", s.max},        {"mean", s.mean},
                        {"std", s.std}};
    // Where the highest sample is (column, row), e.g. to place a lightning bolt.
    const float* z = hf.data();
    const size_t top = size_t(std::max_element(z, z + hf.size()) - z);
    j["peak"] = {{"column", top % size_t(hf.width())}, {"row", top / size_t(hf.width())}, {"height", z[top]}};
    if (hf.world_size() > 0) j["world_size"] = hf.world_size();
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"terrain", "Generate a fractal terrain heightfield",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<TerrainOptions>();
                    auto& p = o->p;
                    app.add_option("--method", p.method,
                                   "terrain method: midpoint and additions make (2^levels + 1)^2 grids; fbm, "
                                   "spectral, interpolated and mandelbrot any --size")
                        ->transform(choice(kMethods))->default_str(name_of(kMethods, p.method));
                    app.add_option("--size", o->size,
                                   "fbm/spectral/interpolated/mandelbrot: N (square) or WxH samples, 2..65536 per side "
                                   "[default: 513]");
                    app.add_option("--levels", p.levels, "refinement steps n: (2^n + 1)^2 samples")
                        ->check(CLI::Range(1, 15))->capture_default_str();
                    app.add_option("--hurst", p.hurst, "Hurst exponent H")->check(CLI::Range(0.0, 1.0))
                        ->capture_default_str();
                    app.add_option("--sigma", p.sigma, "vertical scale (> 0)")->capture_default_str();
                    app.add_option("--seed", p.seed, "random seed (64-bit)")->capture_default_str();
                    app.add_flag("--periodic", p.periodic,
                                 "tileable: wrap-around neighbours (midpoint, additions, interpolated), whole "
                                 "cells per period (fbm, without rotation); spectral always tiles");
                    app.add_option("--octaves", p.octaves, "fbm: number of octaves, 1..30 (the finest must stay "
                                                           "within float resolution)")
                        ->capture_default_str();
                    app.add_option("--lacunarity", p.lacunarity,
                                   "fbm: frequency ratio between octaves (> 1, e.g. 2.01); interpolated: the "
                                   "spacing ratio 1/r per cycle, in (1, 16]")
                        ->capture_default_str();
                    app.add_option("--gain", p.gain,
                                   "fbm: amplitude ratio G between octaves, in (0, 1]; overrides --hurst "
                                   "[default: lacunarity^-H]");
                    app.add_option("--basis", p.basis, "fbm: noise basis")
                        ->transform(choice(kBases))->default_str(name_of(kBases, p.basis));
                    app.add_option("--variant", p.variant,
                                   "fbm: octave combination (hybrid and hetero are Musgrave's multifractals)")
                        ->transform(choice(kVariants))->default_str(name_of(kVariants, p.variant));
                    app.add_option("--frequency", p.frequency, "fbm: base-octave cells across the width (> 0)")
                        ->capture_default_str();
                    app.add_option("--offset", p.offset, "fbm: offset of the ridged, hybrid and hetero variants")
                        ->capture_default_str();
                    app.add_option("--octave-rotation", p.octave_rotation, "fbm: domain rotation per octave, radians")
                        ->capture_default_str();
                    app.add_option("--warp", p.warp, "fbm: domain-warp strength in base cells, 0 (off)..64")
                        ->capture_default_str();
                    app.add_option("--center", o->center,
                                   "mandelbrot: centre of the view in the complex plane, X,Y in [-4, 4] "
                                   "(row 0 is the top) [default: -0.5,0]");
                    app.add_option("--zoom", p.zoom,
                                   "mandelbrot: the width spans 4 / zoom of the plane; >= 1e-3, up to where double "
                                   "precision runs out (about 1e11 at 1025 samples across)")
                        ->capture_default_str();
                    app.add_option("--iterations", p.iterations,
                                   "mandelbrot: maximum iterations, 1..16777216; points that have not escaped are "
                                   "inside the set, a plateau at the height of this escape time")
                        ->capture_default_str();
                    app.add_option("--supersample", p.supersample,
                                   "mandelbrot: k x k points of the plane averaged per sample, 1..8 (smooths the "
                                   "boundary, k^2 times the work)")
                        ->capture_default_str();
                    app.add_option("--curves", o->curves,
                                   "mandelbrot: escape times whose level curves (equipotentials) to write, e.g. "
                                   "2,3,4,6,8")
                        ->delimiter(',');
                    app.add_option("--curves-out", o->curves_out,
                                   "mandelbrot: the --curves polylines as .csv or .json (x = column, y = row, z = "
                                   "height, as fracterra coastline writes them)");
                    app.add_flag("--curves-world", o->curves_world,
                                 "mandelbrot: write the curves' x, y in world units (--world-size across x)");
                    app.add_option("--reference", o->reference,
                                   "reference grid (2^m + 1)^2: " + std::string(kHeightfieldReadHelp) +
                                       "; its values survive exactly (a DEM: see fracterra refine)")
                        ->check(CLI::ExistingFile);
                    app.add_option("--reference-scale", p.reference_scale,
                                   "displacement scale when refining references: sigma as given, or the mean "
                                   "|value| or std of the references")
                        ->transform(choice(kRefScales))->default_str(name_of(kRefScales, p.reference_scale));
                    app.add_option("--world-size", p.world_size, "extent along x in scene units (> 0); heights share the unit")
                        ->capture_default_str();
                    app.add_option("--threads", p.threads, "worker threads, 0 = all cores (output never depends on it)")
                        ->check(CLI::Range(0, 1024))->capture_default_str();
                    app.add_option("--erode", o->erode,
                                   "then erode it with a preset: valleys (fluvial), rain (hydraulic), scree "
                                   "(thermal) or land (all three); see fracterra erode");
                    app.add_option("--out", o->out,
                                   "output .png (16-bit), .pgm (16-bit), .npy (float32), .tif (COG float32), "
                                   ".exr (float) or .raw/.r16 (RAW16 + sidecar .json)");
                    app.add_option("--pov", o->pov, "also write a POV-Ray scene (.pov, with its PNG beside it)");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, min, max, mean, std");
                    return [o] {
                      if (o->out.empty() && o->pov.empty() && !o->stats) invalid("give --out FILE, --pov FILE and/or --stats");
                      return run(*o);
                    };
                  },
                  10});

}  // namespace
}  // namespace ft::cli
