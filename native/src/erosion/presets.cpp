// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion presets and the maps folder (see presets.hpp).
#include "erosion/presets.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"

namespace ft::erosion {
namespace {

// Every preset is a run of the landscape model (years, world units) on the
// defaults; they differ in how soft the rock is, how much the slopes creep,
// how readily rivers drop their load, the scree angle and how soon steep
// slopes shed to it (Scree Slopes, 12x sooner than the rest). Tuned on the
// add-on's default mountain and on fBm terrains (10 world units across,
// relief 1-4) so that Strength 0.5 keeps the landform (tests/native/
// erosion_model_test.cpp), and so that each looks like its name
// (tests/native/erosion_presets_test.cpp): Gentle Valleys cuts least and
// creeps most (the gentlest slopes), Alluvial Fans lays everything down
// (G 1) with the creep that feeds its fans, Badlands keeps the least.
// Badlands' denser gullies need less creep, which roughened the hillslopes
// and stood the edge rows out of the map (docs/erosion.md).
struct Recipe {
  ErosionPreset preset;
  double erodibility, area_exponent, diffusion, deposition, talus_degrees;
  double scree_years = ModelConfig{}.scree_years;
};

constexpr double kYears = 100000;

const Recipe kRecipes[] = {
    {{"gentle_valleys", "Gentle Valleys", "valleys",
      "Rounded hills and soft valleys that widen downstream; gentler slopes than the others"},
     1.5e-5, 0.5, 2.5e-7, 0.1, 33},
    {{"rugged_mountains", "Rugged Mountains", "land",
      "Sharp ridges, deep branching gullies and scree below the cliffs"},
     2.8e-5, 0.5, 1e-7, 0.3, 40},
    {{"badlands", "Badlands", "",
      "Gullies on bare soft rock with steep sides (45 degree scree); little sediment kept"},
     2.2e-5, 0.45, 1e-7, 0.05, 45},
    {{"alluvial_fans", "Alluvial Fans", "rain",
      "Valleys that empty into wide fans and filled plains at the foot of the slopes"},
     2.5e-5, 0.5, 3e-7, 1.0, 35},
    {{"scree_slopes", "Scree Slopes", "scree",
      "Slopes worn back to the scree angle with shallow gullies"},
     8e-6, 0.5, 1.5e-7, 0.5, 30, 8e3},
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

std::vector<std::string> erosion_preset_names() {
  std::vector<std::string> names;
  for (const auto& r : kRecipes) names.push_back(r.preset.id);
  return names;
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
    c.model.scree_years = r.scree_years;
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

Heightfield read_erosion_map(const std::string& dir, const std::string& name) {
  const std::string index_path = dir + "/maps.json";
  nlohmann::json index;
  try {
    index = nlohmann::json::parse(io::read_file(index_path));
  } catch (const nlohmann::json::exception& e) {
    fail(FT_ERR_FORMAT, "'" + index_path + "' is not the maps.json of fracterra erode --maps: " + e.what());
  }
  if (!index.contains(name) || !index[name].is_object() || !index[name].contains("file"))
    fail(FT_ERR_FORMAT, "'" + index_path + "' lists no map '" + name + "' (written by fracterra erode --maps)");
  const nlohmann::json& entry = index[name];
  if (entry.contains("float_file")) return io::read_heightfield(dir + "/" + entry["float_file"].get<std::string>());
  Heightfield hf = io::read_heightfield(dir + "/" + entry["file"].get<std::string>());
  if (entry.value("scale", "linear") == "log10")
    for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(std::pow(10.0, double(hf.data()[i])));
  return hf;
}

void write_erosion_maps(const ErosionMaps& maps, const std::string& dir, const std::string& float_format) {
  if (!float_format.empty() && float_format != ".tif" && float_format != ".exr")
    invalid("the maps' float format must be .tif or .exr, got '" + float_format + "'");
  const std::pair<const char*, const Heightfield*> all[] = {
      {"drainage_area", &maps.drainage_area}, {"slope", &maps.slope},         {"curvature", &maps.curvature},
      {"water_depth", &maps.water_depth},     {"eroded", &maps.eroded},       {"deposited", &maps.deposited}};
  const char* units[] = {"world units^2", "rise/run", "1/world units", "world units", "world units", "world units"};
  nlohmann::json index = nlohmann::json::object();
  int k = 0;
  for (const auto& [name, hf] : all) {
    const std::string file = std::string(name) + ".png";
    const HeightStats s = hf->stats();
    nlohmann::json entry = {{"file", file}, {"min", s.min}, {"max", s.max}, {"unit", units[k++]}};
    if (hf == &maps.drainage_area) {
      // Drainage area spans cells to the whole map (1 to 10^6 at 1025^2): a
      // linear 16-bit step is then several cells, and every hillslope value
      // is blurred. Its log10 keeps the same relative precision everywhere.
      // In double, rounded once to float: libm's log10f differs by an ulp
      // between glibc and Windows' C runtime, the double one (rounded) does
      // not, so the map has the same bits on both (tests/windows).
      Heightfield log_area(hf->width(), hf->height());
      log_area.set_world_size(hf->world_size());
      log_area.set_georef(hf->georef());
      for (size_t i = 0; i < hf->size(); ++i)
        log_area.data()[i] = float(std::log10(double(std::max(hf->data()[i], 1e-30f))));
      io::write_heightfield(log_area, dir + "/" + file);
      const HeightStats l = log_area.stats();
      entry["scale"] = "log10";
      entry["encoded_min"] = l.min;
      entry["encoded_max"] = l.max;
      entry["decode"] = "value = 10^(encoded_min + v / 65535 x (encoded_max - encoded_min)) for a 16-bit sample v";
    } else {
      io::write_heightfield(*hf, dir + "/" + file);
      entry["scale"] = "linear";
    }
    if (!float_format.empty()) {
      const std::string float_file = std::string(name) + float_format;
      io::write_heightfield(*hf, dir + "/" + float_file);  // float32, linear, the values themselves
      entry["float_file"] = float_file;
    }
    index[name] = entry;
  }
  io::write_file_atomically(dir + "/maps.json", index.dump(2) + "\n");
}

}  // namespace ft::erosion
