#include "erosion/erosion_params.hpp"

#include <cfloat>

namespace ft {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr double kMaxSteps = erosion::kMaxErosionSteps;
constexpr uint32_t kAbi212 = 0x2000C;  // uplift_follows_terrain
// The defaults are ErosionConfig's (erosion.hpp); the test
// ErosionParams.TableDefaultsAreTheConfigDefaults holds them together.

#define ROW(field, type) FT_PARAM_ROW(ft_erosion_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_erosion_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_erosion_params), set by ft_erosion_params_init", .methods = kAll},
    {ROW(fluvial_steps, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kMaxSteps,
     .soft_min = 0, .soft_max = 200, .unit = "steps", .label = "River Steps",
     .doc = "Fluvial time steps: stream-power incision with hillslope diffusion, solved implicitly "
            "(Braun & Willett 2013); 0: off",
     .methods = kAll},
    {ROW(fluvial_dt, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .element_kind = -1,
     .default_value = 1000, .hard_min = 0, .hard_max = DBL_MAX, .soft_min = 100, .soft_max = 10000, .unit = "years",
     .label = "Step Length", .doc = "Years per fluvial time step", .methods = kAll},
    {ROW(erodibility, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 2e-4, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 2e-3, .unit = "1/yr", .label = "Erodibility",
     .doc = "Stream-power erodibility K in dz/dt = U - K A^m S (areas in world units^2)", .methods = kAll},
    {ROW(area_exponent, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.5, .hard_min = 0, .hard_max = 2,
     .soft_min = 0.3, .soft_max = 0.7, .unit = "", .label = "Area Exponent",
     .doc = "m in K A^m S (slope exponent n = 1); the concavity of graded rivers is m / n", .methods = kAll},
    // Label "Diffusion", not "Hillslope Diffusion": Blender's narrow sidebar cut the longer one.
    {ROW(diffusion, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 1e-7, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 1e-5, .unit = "world units^2/yr", .label = "Diffusion",
     .doc = "Hillslope diffusivity D in dz/dt = D laplacian(z), implicit; 0: none", .methods = kAll},
    {ROW(uplift, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 1e-3, .unit = "world units/yr", .label = "Uplift",
     .doc = "Uplift rate U of every cell; bounded edges erode towards the lowest input height", .methods = kAll},
    {ROW(hydraulic_iterations, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = kMaxSteps, .soft_min = 0, .soft_max = 300, .unit = "passes", .label = "Rain Passes",
     .doc = "Hydraulic passes: water, sediment capacity, erosion, deposition, evaporation on the grid "
            "(virtual pipes, Mei, Decaudin & Hu 2007); 0: off",
     .methods = kAll},
    {ROW(hydraulic_dt, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.02, .hard_min = 1e-6, .hard_max = 1,
     .soft_min = 0.005, .soft_max = 0.05, .unit = "seconds", .label = "Pass Length",
     .doc = "Seconds per hydraulic pass", .methods = kAll},
    {ROW(rain, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.01, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 0.05, .unit = "world units", .label = "Rain",
     .doc = "Water depth added to every cell per hydraulic pass", .methods = kAll},
    {ROW(evaporation, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.02, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 0.2, .unit = "", .label = "Evaporation",
     .doc = "Fraction of the water evaporated per hydraulic pass", .methods = kAll},
    {ROW(capacity, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 1, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 5, .unit = "", .label = "Capacity",
     .doc = "Sediment capacity constant Kc in C = Kc sin(tilt) |v|", .methods = kAll},
    {ROW(dissolve, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.3, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Dissolving",
     .doc = "Fraction of the capacity deficit taken from the bed per pass", .methods = kAll},
    {ROW(deposit, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.3, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Deposition",
     .doc = "Fraction of the sediment above capacity laid down per pass", .methods = kAll},
    {ROW(thermal_iterations, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = kMaxSteps, .soft_min = 0, .soft_max = 100, .unit = "passes", .label = "Scree Passes",
     .doc = "Thermal passes: material above the talus angle slides down (Musgrave, Kolb & Mace 1989); 0: off",
     .methods = kAll},
    {ROW(talus_degrees, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 33, .hard_min = 0, .hard_max = 89,
     .soft_min = 20, .soft_max = 45, .unit = "degrees", .label = "Talus Angle",
     .doc = "Angle of repose: steeper slopes shed material", .methods = kAll},
    {ROW(thermal_rate, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .element_kind = -1,
     .default_value = 0.5, .hard_min = 0, .hard_max = 1, .soft_min = 0.1, .soft_max = 1, .unit = "",
     .label = "Scree Rate", .doc = "Fraction of the excess over the talus slope moved per pass", .methods = kAll},
    {ROW(periodic, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Tiles",
     .doc = "The terrain tiles: eroded as a torus, it stays seamless", .methods = kAll},
    {ROW(threads, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1024,
     .soft_min = 0, .soft_max = 64, .unit = "threads", .label = "Threads",
     .doc = "Worker threads, 0: all cores; the output never depends on it", .methods = kAll},
    {ROW(progress, FT_PARAM_CALLBACK), .flags = kData, .element_kind = -1, .unit = "", .label = "Progress",
     .doc = "Called as erosion advances; may cancel; NULL: none", .methods = kAll},
    {ROW(progress_user, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_OPAQUE, .element_kind = -1,
     .unit = "", .label = "Progress Data", .doc = "Passed to the progress callback", .methods = kAll},
    {ROW(uplift_follows_terrain, FT_PARAM_BOOL), .since = kAbi212, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Uplift Follows Terrain",
     .doc = "Each cell rises at Uplift x its input height above the lowest over the input's relief, so a "
            "landform keeps its shape (a plain at the lowest height stays); off: every cell at the Uplift rate",
     .methods = kAll},
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& erosion_param_table() {
  static const ParamTable table{"ft_erosion_params", sizeof(ft_erosion_params), kRows};
  return table;
}

namespace erosion {

ft_erosion_params to_c(const ErosionConfig& c) {
  ft_erosion_params p = defaults_of<ft_erosion_params>(erosion_param_table());
  p.fluvial_steps = c.fluvial.steps;
  p.fluvial_dt = c.fluvial.dt;
  p.erodibility = c.fluvial.k;
  p.area_exponent = c.fluvial.m;
  p.diffusion = c.fluvial.diffusion;
  p.uplift = c.fluvial.uplift;
  p.uplift_follows_terrain = c.fluvial.uplift_follows_terrain;
  p.hydraulic_iterations = c.hydraulic.iterations;
  p.hydraulic_dt = c.hydraulic.dt;
  p.rain = c.hydraulic.rain;
  p.evaporation = c.hydraulic.evaporation;
  p.capacity = c.hydraulic.capacity;
  p.dissolve = c.hydraulic.dissolve;
  p.deposit = c.hydraulic.deposit;
  p.thermal_iterations = c.thermal.iterations;
  p.talus_degrees = c.thermal.talus_degrees;
  p.thermal_rate = c.thermal.rate;
  p.periodic = c.periodic;
  p.threads = c.threads;
  return p;
}

ErosionConfig from_c(const ft_erosion_params& given) {
  const ft_erosion_params p = upgraded(erosion_param_table(), given);
  check_ranges(erosion_param_table(), &p);
  ErosionConfig c;
  c.fluvial = {p.fluvial_steps, p.fluvial_dt, p.erodibility, p.area_exponent, p.diffusion, p.uplift,
               p.uplift_follows_terrain != 0};
  c.hydraulic.iterations = p.hydraulic_iterations;
  c.hydraulic.dt = p.hydraulic_dt;
  c.hydraulic.rain = p.rain;
  c.hydraulic.evaporation = p.evaporation;
  c.hydraulic.capacity = p.capacity;
  c.hydraulic.dissolve = p.dissolve;
  c.hydraulic.deposit = p.deposit;
  c.thermal = {p.thermal_iterations, p.talus_degrees, p.thermal_rate};
  c.periodic = p.periodic != 0;
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace erosion
}  // namespace ft
