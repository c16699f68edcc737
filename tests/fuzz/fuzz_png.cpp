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
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  ft::fuzz::expect_ok_or_error([&] {
    const ft::GrayImage img = ft::decode_png(bytes);
    if (img.width < 1 || img.height < 1 || img.pixels.size() != size_t(img.width) * size_t(img.height))
      ft::fuzz::bug("decoded image size does not match its pixels");
    if (img.bit_depth != 8 && img.bit_depth != 16) ft::fuzz::bug("bit depth neither 8 nor 16");
    const ft::Heightfield hf = ft::image_to_heightfield(img);
    if (hf.width() != img.width || hf.height() != img.height) ft::fuzz::bug("heightfield size differs from the image");
  });
  return 0;
}
