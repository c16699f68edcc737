// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the C ABI the way ctypes callers can get it wrong: raw bytes become
// the fields of ft_terrain_params / ft_profile_params / ft_polyline_params /
// ft_fractalize_params / ft_hurst_params / ft_clouds_params (struct_size
// included; the last two over a small heightfield of input floats, NaN and
// infinities included), with pointer fields (reference
// grid, falloff mask, base polyline, IFS table, weights) holding what their counts claim,
// and a progress callback that cancels after a few reports. Every call must return a known status
// with a message, hand back either a complete result or NULL, and never
// crash, leak or hang (the memory cap keeps accepted sizes small).
#include <memory>
#include <vector>

#include "fracterra/fracterra.h"
#include "fuzz_util.hpp"

namespace {

using ft::fuzz::bug;
using ft::fuzz::Bytes;

struct CancelAfter {
  int32_t reports_left;
};

int32_t cancel_after(void* user, double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) bug("progress fraction outside [0, 1]");
  auto* c = static_cast<CancelAfter*>(user);
  return c->reports_left-- <= 0 ? 1 : 0;
}

void check_status(ft_status s) {
  if (s < FT_OK || s > FT_ERR_INTERNAL) bug("unknown status " + std::to_string(s));
  if (s == FT_ERR_INTERNAL) bug(std::string("FT_ERR_INTERNAL: ") + ft_last_error());
  if (s != FT_OK && ft_last_error()[0] == '\0') bug("a failure without a message");
  if (s == FT_OK && ft_last_error()[0] != '\0') bug("a success with an error message");
}

// Decides the pointer fields: they cannot be random bytes, but whether they
// are set, how big the reference really is and when to cancel can.
struct Pointers {
  std::vector<float> reference;
  CancelAfter cancel{0};
  bool use_reference = false, use_progress = false;

  void take(Bytes& in, int64_t claimed_values) {
    const uint8_t flags = in.take<uint8_t>();
    use_reference = flags & 1;
    use_progress = flags & 2;
    cancel.reports_left = in.take<uint8_t>() % 16;
    // The reference holds exactly the values its size claims (a caller
    // passing a shorter array is outside the contract), from the input.
    if (use_reference && claimed_values >= 0 && claimed_values <= 65 * 65) {
      reference.resize(size_t(claimed_values));
      for (float& v : reference) v = in.left() >= 4 ? in.take<float>() : float(in.take<uint8_t>());
    } else {
      use_reference = false;
    }
  }
};

void fuzz_terrain(Bytes& in) {
  ft_terrain_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  // Mostly a valid struct_size, or the checks behind it are never reached.
  if (fixups & 1) p.struct_size = sizeof p;
  // Up to 1024 threads is valid, but starting a thousand threads per call
  // would make the fuzzer crawl: valid counts are folded to 0..2.
  if (p.threads >= 0 && p.threads <= 1024) p.threads %= 3;
  Pointers ptr;
  const int64_t side = p.reference_size;
  ptr.take(in, side >= 0 && side <= 65 ? side * side : -1);
  p.reference = ptr.use_reference ? ptr.reference.data() : nullptr;
  p.progress = ptr.use_progress ? cancel_after : nullptr;
  p.progress_user = &ptr.cancel;
  // The custom falloff's mask holds what its sides claim (small ones only),
  // values from the input: in and out of [0, 1], NaN included.
  std::vector<float> mask;
  const int64_t mw = p.falloff_mask_width, mh = p.falloff_mask_height;
  if ((fixups & 2) && mw >= 0 && mh >= 0 && mw <= 65 && mh <= 65) {
    mask.resize(size_t(mw * mh));
    for (float& v : mask) v = in.left() >= 4 ? in.take<float>() : float(in.take<uint8_t>()) / 255.0f;
    p.falloff_mask = mask.data();
  } else {
    p.falloff_mask = nullptr;
  }

  ft_heightfield* hf = reinterpret_cast<ft_heightfield*>(&p);  // must be overwritten
  const ft_status s = ft_terrain_generate(&p, &hf);
  check_status(s);
  if (s != FT_OK) {
    if (hf != nullptr) bug("failed call left a handle behind");
    return;
  }
  if (!hf) bug("FT_OK without a heightfield");
  const int32_t w = ft_heightfield_width(hf), h = ft_heightfield_height(hf);
  if (w < 2 || h < 2 || !ft_heightfield_data(hf)) bug("bad heightfield shape");
  if ((p.method == FT_TERRAIN_MIDPOINT || p.method == FT_TERRAIN_ADDITIONS) &&
      (w != ft_terrain_side(p.levels) || h != w))
    bug("midpoint terrain of the wrong side");
  double mn, mx, mean, sd;
  check_status(ft_heightfield_stats(hf, &mn, &mx, &mean, &sd));
  std::vector<float> copy(size_t(w) * size_t(h));
  check_status(ft_heightfield_copy(hf, copy.data(), copy.size()));
  if (ft_heightfield_copy(hf, copy.data(), copy.size() - 1) != FT_ERR_INVALID_ARGUMENT)
    bug("a short copy buffer was accepted");
  ft_heightfield_free(hf);
}

void fuzz_profile(Bytes& in) {
  ft_profile_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  if (fixups & 1) p.struct_size = sizeof p;
  Pointers ptr;
  ptr.take(in, p.reference_size);
  p.reference = ptr.use_reference ? ptr.reference.data() : nullptr;
  p.progress = ptr.use_progress ? cancel_after : nullptr;
  p.progress_user = &ptr.cancel;
  // The caller's buffer: the documented length (while small), sometimes one short.
  const int64_t len = ft_profile_length(p.levels);
  size_t count = len > 0 && len <= (int64_t(1) << 16) + 1 ? size_t(len) : 17;
  if ((fixups & 2) && count > 0) --count;
  std::vector<float> dst(count);
  const ft_status s = ft_profile_generate(&p, (fixups & 4) ? nullptr : dst.data(), count);
  check_status(s);
  if (s == FT_OK && (len < 0 || size_t(len) > count)) bug("profile written past the buffer it was given");
}

void fuzz_polyline(Bytes& in) {
  ft_polyline_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  if (fixups & 1) p.struct_size = sizeof p;
  if (p.threads >= 0 && p.threads <= 1024) p.threads %= 3;  // as for terrains
  // The base polyline and the IFS table hold exactly what their counts
  // claim (small counts only), from the input.
  std::vector<double> base, table;
  if ((fixups & 4) && p.base_count >= 0 && p.base_count <= 64) {
    base.resize(size_t(p.base_count) * 3);
    for (double& v : base) v = in.left() >= 8 ? in.take<double>() : double(in.take<uint8_t>());
    p.base = base.data();
  } else {
    p.base = nullptr;
  }
  if ((fixups & 8) && p.ifs_maps >= 0 && p.ifs_maps <= 64) {
    table.resize(size_t(p.ifs_maps) * 7);
    for (double& v : table) v = in.left() >= 8 ? in.take<double>() : double(in.take<uint8_t>()) / 255.0;
    p.ifs_table = table.data();
  } else {
    p.ifs_table = nullptr;
  }
  CancelAfter cancel{in.take<uint8_t>() % 16};
  p.progress = (fixups & 16) ? cancel_after : nullptr;
  p.progress_user = &cancel;
  ft_polylines* out = reinterpret_cast<ft_polylines*>(&p);
  const ft_status s = ft_polyline_generate(&p, &out);
  check_status(s);
  if (s != FT_OK) {
    if (out != nullptr) bug("failed call left a handle behind");
    return;
  }
  const int64_t lines = ft_polylines_line_count(out), verts = ft_polylines_vertex_count(out);
  const int64_t* off = ft_polylines_offsets(out);
  if (lines < 1 || !off || off[0] != 0 || off[lines] != verts) bug("inconsistent polyline set");
  ft_polyline_stats st;
  check_status(ft_polyline_measure(out, &st));
  ft_polylines_free(out);
}

// A unit cube: the fractalize parameters vary, the mesh does not (the OBJ
// harness varies meshes).
void fuzz_fractalize(Bytes& in) {
  static const float kCube[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  static const int32_t kSizes[] = {4, 4, 4, 4, 4, 4};
  static const int32_t kFaces[] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  ft_mesh* cube = nullptr;
  check_status(ft_mesh_create(kCube, 8, kSizes, 6, kFaces, nullptr, nullptr, 0, &cube));
  ft_fractalize_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  if (fixups & 1) p.struct_size = sizeof p;
  if (p.threads >= 0 && p.threads <= 1024) p.threads %= 3;
  std::vector<float> weights(8);
  for (float& w : weights) w = in.take<float>();
  p.weights = (fixups & 2) ? weights.data() : nullptr;
  CancelAfter cancel{in.take<uint8_t>() % 16};
  p.progress = (fixups & 4) ? cancel_after : nullptr;
  p.progress_user = &cancel;
  ft_mesh* out = reinterpret_cast<ft_mesh*>(&p);
  const ft_status s = ft_fractalize(cube, &p, &out);
  check_status(s);
  if (s != FT_OK && out != nullptr) bug("failed call left a handle behind");
  if (s == FT_OK && (ft_mesh_face_count(out) < 6 || ft_mesh_vertex_count(out) < 8)) bug("mesh shrank");
  ft_mesh_free(s == FT_OK ? out : nullptr);
  ft_mesh_free(cube);
}

// A width x height heightfield (each 4..35) of the input's floats (or bytes when it runs short).
ft_heightfield* small_heightfield(Bytes& in) {
  const int32_t w = 4 + in.take<uint8_t>() % 32, h = 4 + in.take<uint8_t>() % 32;
  std::vector<float> z(size_t(w) * size_t(h));
  for (float& v : z) v = in.left() >= 4 ? in.take<float>() : float(in.take<uint8_t>());
  ft_heightfield* hf = nullptr;
  check_status(ft_heightfield_create(w, h, z.data(), &hf));
  return hf;
}

// [which = 4] [ft_hurst_params] [fixups: 1 = set struct_size, 2 = NULL params (the
// defaults), 4 = also row 0 as a profile] [w] [h] [floats...]
void fuzz_hurst(Bytes& in) {
  ft_hurst_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  if (fixups & 1) p.struct_size = sizeof p;
  const ft_hurst_params* given = (fixups & 2) ? nullptr : &p;
  ft_heightfield* hf = small_heightfield(in);
  if (!hf) return;
  ft_hurst_result r{};
  r.struct_size = sizeof r;
  const ft_status s = ft_hurst_heightfield(hf, given, &r);
  check_status(s);
  if (s == FT_OK && (r.method < FT_HURST_VARIOGRAM || r.method > FT_HURST_SPECTRAL)) bug("no estimator reported");
  if (fixups & 4) {
    r = ft_hurst_result{};
    r.struct_size = sizeof r;
    check_status(ft_hurst_profile(ft_heightfield_data(hf), size_t(ft_heightfield_width(hf)), given, &r));
  }
  ft_heightfield_free(hf);
}

// [which = 5] [ft_clouds_params] [fixups: 1 = set struct_size, 2 = buffer one short] [w] [h] [floats...]
void fuzz_clouds(Bytes& in) {
  ft_clouds_params p;
  in.take_into(&p, sizeof p);
  const uint8_t fixups = in.take<uint8_t>();
  if (fixups & 1) p.struct_size = sizeof p;
  ft_heightfield* hf = small_heightfield(in);
  if (!hf) return;
  const size_t n = size_t(ft_heightfield_width(hf)) * size_t(ft_heightfield_height(hf));
  std::vector<uint16_t> grey(n);
  const ft_status s = ft_clouds(hf, &p, grey.data(), (fixups & 2) ? n - 1 : n);
  check_status(s);
  if ((fixups & 2) && s == FT_OK) bug("clouds wrote into a buffer one short");
  if (s == FT_OK && p.bit_depth == 8)
    for (uint16_t g : grey)
      if (g > 255) bug("an 8-bit cloud above 255");
  ft_heightfield_free(hf);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft_set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  switch (in.take<uint8_t>() % 6) {
    case 0: fuzz_terrain(in); break;
    case 1: fuzz_profile(in); break;
    case 2: fuzz_polyline(in); break;
    case 3: fuzz_fractalize(in); break;
    case 4: fuzz_hurst(in); break;
    default: fuzz_clouds(in); break;
  }
  return 0;
}
