// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the .npy reader: decode_npy (1D profiles and 2D heightfields) and the
// heightfield conversion of decode_heightfield.
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/heightfield_io.hpp"
#include "io/npy.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  bool two_d = false;
  ft::fuzz::expect_ok_or_error([&] {
    const ft::io::NpyArray a = ft::io::decode_npy(bytes);
    uint64_t count = 1;
    for (int64_t d : a.shape) {
      if (d < 0) ft::fuzz::bug("negative dimension");
      count *= uint64_t(d);
    }
    if (a.shape.empty() || a.shape.size() > 2 || count != a.values.size())
      ft::fuzz::bug("shape does not match the values");
    two_d = a.shape.size() == 2;
  });
  if (two_d) {
    ft::fuzz::expect_ok_or_error([&] {
      const ft::Heightfield hf = ft::io::decode_heightfield(bytes, ".npy");
      if (hf.size() == 0) ft::fuzz::bug("empty heightfield accepted");
    });
  }
  return 0;
}
