// Erosion presets and the maps folder (see presets.hpp).
#include "erosion/presets.hpp"

#include <algorithm>
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
      Heightfield log_area(hf->width(), hf->height());
      log_area.set_world_size(hf->world_size());
      log_area.set_georef(hf->georef());
      for (size_t i = 0; i < hf->size(); ++i) log_area.data()[i] = float(std::log10(std::max(hf->data()[i], 1e-30f)));
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
