// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the OpenEXR reader (decode_exr: header limits, channel choice, the
// memory stream, size checks against the memory cap).
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/exr.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  ft::fuzz::expect_ok_or_error([&] {
    const ft::Heightfield hf = ft::io::decode_exr(bytes);
    if (hf.size() == 0) ft::fuzz::bug("empty heightfield accepted");
  });
  return 0;
}
