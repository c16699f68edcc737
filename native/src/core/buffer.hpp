// SPDX-License-Identifier: GPL-3.0-or-later
// A heap array that is not zero-filled on allocation: generators overwrite
// every sample, and zero-filling 8193^2 floats would cost a third of the run.
// Large buffers are 2 MiB-aligned blocks advised to use transparent huge pages:
// a 268 MB terrain then takes ~130 page faults on first touch instead of
// ~65000 (where the kernel allows it; otherwise the advice is ignored).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

#include "core/platform_memory.hpp"

namespace ft {

namespace detail {

// Large buffers start at one of 16 offsets into their 2 MiB-aligned block,
// in turn. Aligned alike, arrays read side by side in one loop (the 16 of a
// hydraulic pass, the maps of an erosion) put the elements of one index in
// the same cache set and evict each other: that made erosion at 1025^2 1.5
// times slower. 4224 bytes apart (66 lines) they fall in different sets of
// the L1 (4 KiB period) and L2 (128 KiB period) caches.
inline constexpr size_t kHuge = size_t(2) << 20;
inline constexpr size_t kColourStep = 4224;
inline constexpr unsigned kColours = 16;

inline size_t next_colour_offset() {
  static std::atomic<unsigned> next{0};
  return size_t(next.fetch_add(1, std::memory_order_relaxed) % kColours) * kColourStep;
}

struct FreeDeleter {
  size_t offset = 0;  // from the allocation's start to the data
  void operator()(void* p) const noexcept { platform::aligned_free(static_cast<char*>(p) - offset); }
};

// Returns the data pointer and sets `offset` (what FreeDeleter takes back).
inline void* allocate_uninitialised(size_t bytes, size_t& offset) {
  const bool huge = bytes >= 2 * kHuge;
  const size_t align = huge ? kHuge : 64;
  offset = huge ? next_colour_offset() : 0;
  const size_t rounded = (bytes + offset + align - 1) / align * align;
  void* p = platform::aligned_allocate(align, rounded == 0 ? align : rounded);
  if (!p) throw std::bad_alloc();
  if (huge) platform::advise_huge_pages(p, rounded);
  return static_cast<char*>(p) + offset;
}
}  // namespace detail

template <class T>
class Buffer {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>,
                "Buffer holds plain data only");

 public:
  Buffer() = default;
  explicit Buffer(size_t n) : size_(n) {
    size_t offset = 0;
    T* p = static_cast<T*>(detail::allocate_uninitialised(n * sizeof(T), offset));
    data_ = std::unique_ptr<T, detail::FreeDeleter>(p, detail::FreeDeleter{offset});
  }

  T* data() noexcept { return data_.get(); }
  const T* data() const noexcept { return data_.get(); }
  size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  T& operator[](size_t i) noexcept { return data_.get()[i]; }
  const T& operator[](size_t i) const noexcept { return data_.get()[i]; }
  T* begin() noexcept { return data_.get(); }
  T* end() noexcept { return data_.get() + size_; }
  const T* begin() const noexcept { return data_.get(); }
  const T* end() const noexcept { return data_.get() + size_; }

 private:
  std::unique_ptr<T, detail::FreeDeleter> data_;
  size_t size_ = 0;
};

}  // namespace ft
