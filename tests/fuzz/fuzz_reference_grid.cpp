// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes terrains and profiles refined from a reference decoded from a file,
// the path of `fracterra terrain --reference` and `fracterra profile
// --reference`: the first byte picks the format and the generator settings,
// the rest is the file. Reference nodes must survive exactly.
#include <cmath>

#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/heightfield_io.hpp"
#include "io/npy.hpp"
#include "terrain/terrain.hpp"

namespace {

using ft::fuzz::bug;

void terrain_from(const ft::Heightfield& ref, uint8_t knobs) {
  ft_terrain_params p = ft::terrain::default_terrain_params();
  p.method = (knobs & 1) ? FT_TERRAIN_ADDITIONS : FT_TERRAIN_MIDPOINT;
  p.periodic = (knobs >> 1) & 1;
  p.reference_scale = ((knobs >> 2) & 3) % 3;
  p.levels = 1 + (knobs >> 4) % 8;
  p.threads = 1;
  if (ref.width() != ref.height()) ft::invalid("the reference grid must be square");  // as the CLI does
  p.reference = ref.data();
  p.reference_size = ref.width();
  const ft::Heightfield hf = ft::terrain::generate_terrain(p);
  const int step = (hf.width() - 1) / (ref.width() - 1);
  for (int32_t j = 0; j < ref.height(); ++j)
    for (int32_t i = 0; i < ref.width(); ++i)
      if (hf.at(i * step, j * step) != ref.at(i, j)) bug("a reference value did not survive");
}

void profile_from(const ft::io::NpyArray& a, uint8_t knobs) {
  if (a.shape.size() != 1) ft::invalid("a profile reference must be 1D");  // as the CLI does
  ft_profile_params p = ft::terrain::default_profile_params();
  p.reference_scale = (knobs & 3) % 3;
  p.levels = 1 + (knobs >> 2) % 16;
  p.reference = a.values.data();
  p.reference_size = int32_t(a.values.size() > (1u << 20) ? -1 : int64_t(a.values.size()));
  std::vector<float> x((size_t(1) << p.levels) + 1);
  ft::terrain::generate_profile(p, x.data(), x.size());
  const size_t step = (x.size() - 1) / (a.values.size() - 1);
  for (size_t i = 0; i < a.values.size(); ++i)
    if (x[i * step] != a.values[i]) bug("a reference value did not survive");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint8_t format = data[0], knobs = data[1];
  const std::string bytes(reinterpret_cast<const char*>(data + 2), size - 2);
  static const char* const kExt[] = {".png", ".pgm", ".npy"};
  ft::fuzz::expect_ok_or_error([&] {
    if (format % 4 == 3) profile_from(ft::io::decode_npy(bytes), knobs);
    else terrain_from(ft::io::decode_heightfield(bytes, kExt[format % 4]), knobs);
  });
  return 0;
}
