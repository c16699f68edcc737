// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the GDAL reader path (decode_gdal: /vsimem/, driver choice, size
// checks against the memory cap, nodata counting and GDALFillNodata). The
// first byte picks the extension GDAL sees and the nodata policy; GDAL's
// own errors must come back as ft::Error, never as output on stderr.
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/gdal_raster.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExt[] = {".tif", ".asc", ".hgt", ".tif"};
  const std::string ext = kExt[data[0] & 3];
  const ft::io::NodataPolicy policy = (data[0] & 4) ? ft::io::NodataPolicy::fill : ft::io::NodataPolicy::refuse;
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  ft::fuzz::expect_ok_or_error([&] {
    const ft::Heightfield hf = ft::io::decode_gdal(bytes, ext, policy);
    if (hf.width() < 2 || hf.height() < 2) ft::fuzz::bug("a raster under 2 x 2 accepted");
    for (size_t i = 0; i < hf.size(); ++i)
      if (!std::isfinite(hf.data()[i])) ft::fuzz::bug("a non-finite height accepted");
  });
  return 0;
}
