// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the polyline JSON reader, and checks that whatever it accepts
// survives a write and re-read exactly (the round trip the format promises).
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/polyline_io.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ft::fuzz::check_polyline_reader(
      data, size, [](const std::string& t) { return ft::io::decode_polylines_json(t); },
      [](const ft::PolylineSet& s) { return ft::io::encode_polylines_json(s); });
  return 0;
}
