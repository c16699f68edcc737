// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the RAW16 reader with its sidecar JSON (io/raw16.cpp): the first
// two bytes give how many of the rest are the samples (little-endian, at
// most what is there), the others are the sidecar's text (empty: no
// sidecar, a square assumed). Whatever it accepts is a heightfield of the
// size the sidecar states, every height a finite float.
#include <cmath>
#include <string>

#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/raw16.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ft::fuzz::Bytes in(data, size);
  const size_t raw_size = in.take<uint16_t>();
  const std::string rest = in.rest();
  const std::string raw = rest.substr(0, raw_size), sidecar = rest.substr(std::min(raw_size, rest.size()));
  ft::fuzz::expect_ok_or_error([&] {
    const ft::Heightfield hf = ft::io::decode_raw16(raw, sidecar, "fuzz.raw");
    if (size_t(hf.width()) * size_t(hf.height()) * 2 != raw.size()) ft::fuzz::bug("size differs from the bytes");
    for (size_t i = 0; i < hf.size(); ++i)
      if (!std::isfinite(hf.data()[i])) ft::fuzz::bug("a height that is not finite");
    if (hf.world_size() < 0 || !std::isfinite(hf.world_size())) ft::fuzz::bug("a bad world size was kept");
  });
  return 0;
}
