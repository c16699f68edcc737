// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the OBJ reader (tinyobjloader plus our crease/corner tags), the
// mesh validation every consumer runs, and fractalization of what passes
// (`fracterra fractalize --in x.obj`): success or ft::Error, never a crash;
// an accepted mesh survives write + read exactly.
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/obj_io.hpp"
#include "subdiv/fractalize.hpp"
#include "subdiv/mesh_validation.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t knobs = data[0];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  ft::fuzz::expect_ok_or_error([&] {
    const ft::Mesh m = ft::io::decode_obj(text);
    ft::subdiv::validate_mesh(m);
    const ft::Mesh back = ft::io::decode_obj(ft::io::encode_obj(m));
    if (back.positions != m.positions || back.face_sizes != m.face_sizes || back.face_indices != m.face_indices)
      ft::fuzz::bug("write + read does not give back the same mesh");
    ft_fractalize_params p = ft::subdiv::default_fractalize_params();
    p.levels = 1 + knobs % 3;
    p.scheme = (knobs >> 2) % 3;
    p.mode = (knobs >> 4) & 1;
    p.fix_boundary = (knobs >> 5) & 1;
    p.scale_by_edge_length = (knobs >> 6) & 1;
    p.threads = 1;
    const ft::Mesh out = ft::subdiv::fractalize(m, p);
    if (out.face_count() == 0) ft::fuzz::bug("fractalize returned no faces");
  });
  return 0;
}
