// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the PGM heightfield reader: decode_pgm and the conversion to a
// heightfield (the path of `fracterra terrain --reference x.pgm`).
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/heightfield_io.hpp"
#include "io/pgm.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ft::fuzz::check_image_reader(data, size, [](const std::string& b) { return ft::io::decode_pgm(b); });
  return 0;
}
