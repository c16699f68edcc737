// SPDX-License-Identifier: GPL-3.0-or-later
// A monotone priority queue of cells by height (Ahuja, Mehlhorn, Orlin &
// Tarjan 1990, "Faster algorithms for the shortest path problem"): keys
// taken out never decrease, as in a Priority-Flood, which visits cells from
// the outlets upward. A key goes to the bucket of the highest bit in which
// it differs from the last key taken; taking one empties the lowest
// non-empty bucket into lower ones. Each item moves at most 32 times, and
// never by a comparison sort: about 2-3x faster than a binary heap here.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace ft::erosion {

class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }

  // Starts a new search (keeps the storage): any height may come next.
  void restart() {
    for (auto& b : buckets_) b.clear();
    last_ = 0;
    size_ = 0;
  }

  // `z` must not be below the height last popped.
  void push(float z, int32_t i) {
    const uint32_t k = key(z);
    buckets_[bucket(k)].push_back({k, i});
    ++size_;
  }

  // A cell of the lowest height; equal heights leave in a fixed order (the
  // result depends only on the pushes, never on a thread count).
  int32_t pop() {
    if (buckets_[0].empty()) {
      size_t b = 1;
      while (buckets_[b].empty()) ++b;
      uint32_t low = UINT32_MAX;
      for (const auto& item : buckets_[b]) low = item.first < low ? item.first : low;
      last_ = low;
      for (const auto& item : buckets_[b]) buckets_[bucket(item.first)].push_back(item);
      buckets_[b].clear();
    }
    const int32_t i = buckets_[0].back().second;
    buckets_[0].pop_back();
    --size_;
    return i;
  }

 private:
  // Orders floats as unsigned integers: negative ones reversed below the
  // positive ones.
  static uint32_t key(float z) {
    const uint32_t bits = std::bit_cast<uint32_t>(z);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
  }
  size_t bucket(uint32_t k) const { return k == last_ ? 0 : size_t(32 - std::countl_zero(k ^ last_)); }

  std::array<std::vector<std::pair<uint32_t, int32_t>>, 33> buckets_;
  uint32_t last_ = 0;
  size_t size_ = 0;
};

}  // namespace ft::erosion
