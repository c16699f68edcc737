// Erosion presets and the maps folder (see presets.hpp).
#include "erosion/presets.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"

namespace ft::erosion {
namespace {

// Every preset is a run of the landscape model (years, world units) on the
// defaults; they differ in how soft the rock is, how much the slopes creep,
// how readily rivers drop their load and the scree angle. Tuned on the
// add-on's default mountain and on fBm terrains (10 world units across,
// relief 1-4) so that Strength 0.5 keeps the landform (tests/native/
// erosion_model_test.cpp).
struct Recipe {
  ErosionPreset preset;
  double erodibility, area_exponent, diffusion, deposition, talus_degrees;
};

constexpr double kYears = 100000;

const Recipe kRecipes[] = {
    {{"gentle_valleys", "Gentle Valleys", "valleys",
      "Rounded hills and soft valleys that widen downstream, with sediment on their floors"},
     2e-5, 0.5, 2e-7, 0.5, 33},
    {{"rugged_mountains", "Rugged Mountains", "land",
      "Sharp ridges, deep branching gullies and scree below the cliffs"},
     3e-5, 0.5, 1e-7, 0.3, 40},
    {{"badlands", "Badlands", "",
      "Dense fine gullies on bare soft rock; little creep, little sediment kept"},
     2.5e-5, 0.45, 1e-7, 0.1, 45},
    {{"alluvial_fans", "Alluvial Fans", "rain",
      "Valleys that empty into wide fans and filled plains at the foot of the slopes"},
     2.5e-5, 0.5, 1e-7, 0.9, 35},
    {{"scree_slopes", "Scree Slopes", "scree",
      "Slopes worn back to the scree angle with shallow gullies"},
     8e-6, 0.5, 1.5e-7, 0.5, 30},
};

// "Gentle Valleys", "gentle-valleys" and "GENTLE_VALLEYS" are one name.
std::string key(const std::string& s) {
  std::string k;
  for (char ch : s) k += (ch == ' ' || ch == '-') ? '_' : char(std::tolower(static_cast<unsigned char>(ch)));
  return k;
}

}  // namespace

std::vector<ErosionPreset> erosion_presets() {
  std::vector<ErosionPreset> all;
  for (const auto& r : kRecipes) all.push_back(r.preset);
  return all;
}

ErosionConfig erosion_preset(const std::string& name) {
  const std::string k = key(name);
  for (const auto& r : kRecipes) {
    if (k != r.preset.id && k != key(r.preset.label) && (r.preset.alias.empty() || k != r.preset.alias)) continue;
    ErosionConfig c;
    c.model.duration = kYears;
    c.model.deposition = r.deposition;
    c.fluvial.erodibility = r.erodibility;
    c.fluvial.area_exponent = r.area_exponent;
    c.fluvial.diffusion = r.diffusion;
    c.thermal.talus_degrees = r.talus_degrees;
    return c;
  }
  std::string known;
  for (const auto& r : kRecipes)
    known += (known.empty() ? "" : ", ") + r.preset.id +
             (r.preset.alias.empty() ? "" : " (or " + r.preset.alias + ")");
  invalid("unknown erosion preset '" + name + "' (known: " + known + ")");
}

ErosionConfig erosion_preset(const std::string& name, const Heightfield& terrain) {
  (void)terrain;  // the presets are in world units and years: nothing to fit
  return erosion_preset(name);
}

void write_erosion_maps(const ErosionMaps& maps, const std::string& dir) {
  const std::pair<const char*, const Heightfield*> all[] = {
      {"drainage_area", &maps.drainage_area}, {"slope", &maps.slope},         {"curvature", &maps.curvature},
      {"water_depth", &maps.water_depth},     {"eroded", &maps.eroded},       {"deposited", &maps.deposited}};
  const char* units[] = {"world units^2", "rise/run", "1/world units", "world units", "world units", "world units"};
  nlohmann::json index = nlohmann::json::object();
  int k = 0;
  for (const auto& [name, hf] : all) {
    const std::string file = std::string(name) + ".png";
    io::write_heightfield(*hf, dir + "/" + file);
    const HeightStats s = hf->stats();
    index[name] = {{"file", file}, {"min", s.min}, {"max", s.max}, {"unit", units[k++]}};
  }
  io::write_file_atomically(dir + "/maps.json", index.dump(2) + "\n");
}

}  // namespace ft::erosion
