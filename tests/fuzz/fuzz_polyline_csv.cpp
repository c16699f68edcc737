// Fuzzes the polyline CSV reader, and checks that whatever it accepts
// survives a write and re-read exactly (the round trip the format promises).
#include "core/memory.hpp"
#include "fuzz_util.hpp"
#include "io/polyline_io.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ft::set_memory_cap(ft::fuzz::kFuzzMemoryCap);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ft::fuzz::expect_ok_or_error([&] {
    const ft::PolylineSet s = ft::decode_polylines_csv(text);
    if (s.offsets.empty() || s.offsets.front() != 0 || s.offsets.back() != s.vertex_count() ||
        s.radii.size() != s.points.size())
      ft::fuzz::bug("inconsistent polyline set");
    for (int64_t i = 0; i < s.line_count(); ++i)
      if (s.line_end(i) <= s.line_begin(i)) ft::fuzz::bug("empty polyline kept");
    const ft::PolylineSet t = ft::decode_polylines_csv(ft::encode_polylines_csv(s));
    if (t.points != s.points || t.radii != s.radii || t.offsets != s.offsets)
      ft::fuzz::bug("write + read does not give back the same polylines");
  });
  return 0;
}
