// SPDX-License-Identifier: GPL-3.0-or-later
// Golden checksums of bit-exact output: the 64-bit FNV-1a of an array's bytes.
// A golden value is recorded from the implementation and changes only when
// the algorithm, its random streams or its float arithmetic change, which
// must be a deliberate, documented decision (saved seeds would change).
#pragma once

#include <cstddef>
#include <cstdint>

namespace ft::test {

inline uint64_t fnv1a(const void* data, size_t bytes, uint64_t h = 1469598103934665603ULL) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

// Of `n` floats (a heightfield or profile).
inline uint64_t checksum(const float* v, size_t n) { return fnv1a(v, n * sizeof(float)); }

}  // namespace ft::test
