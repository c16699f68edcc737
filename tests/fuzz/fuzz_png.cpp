// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the PNG heightfield reader: decode_png and the conversion to a
// heightfield (the path of `fracterra terrain --reference x.png`).
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ft::fuzz::check_image_reader(data, size, [](const std::string& b) { return ft::io::decode_png(b); });
  return 0;
}
