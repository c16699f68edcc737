// Erosion presets and the maps folder (see presets.hpp).
#include "erosion/presets.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"

namespace ft::erosion {

std::vector<std::string> erosion_preset_names() { return {"valleys", "rain", "scree", "land"}; }

ErosionConfig erosion_preset(const std::string& name) {
  ErosionConfig c;
  if (name == "valleys" || name == "land") {
    // Uplift balanced by incision: graded channels (slope ~ area^-m)
    // rather than a decaying landscape. 1e-4 suits a relief of about 6
    // units; erosion_preset(name, terrain) fits it to the terrain.
    c.fluvial.steps = 60;
    c.fluvial.uplift = 1e-4;
  }
  if (name == "rain" || name == "land") c.hydraulic.iterations = name == "land" ? 60 : 120;
  if (name == "scree" || name == "land") c.thermal.iterations = name == "land" ? 10 : 40;
  if (c.fluvial.steps + c.hydraulic.iterations + c.thermal.iterations == 0) {
    std::string known;
    for (const auto& n : erosion_preset_names()) known += (known.empty() ? "" : ", ") + n;
    invalid("unknown erosion preset '" + name + "' (known: " + known + ")");
  }
  return c;
}

ErosionConfig erosion_preset(const std::string& name, const Heightfield& terrain) {
  ErosionConfig c = erosion_preset(name);
  if (c.fluvial.uplift > 0) {
    const HeightStats s = terrain.stats();
    const double relief = s.max - s.min, years = double(c.fluvial.steps) * c.fluvial.dt;
    c.fluvial.uplift = std::isfinite(relief) && relief > 0 ? relief / years : 0;
    // In proportion to each cell's height: a landform on a plain keeps its
    // shape (uniform uplift raised the plain too, into a dissected plateau
    // with walls at the edges).
    c.fluvial.uplift_follows_terrain = true;
  }
  return c;
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
