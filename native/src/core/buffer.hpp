// A heap array that is not zero-filled on allocation: generators overwrite
// every sample, and zero-filling 8193^2 floats would cost a third of the run.
// Large buffers are 2 MiB aligned and advised to use transparent huge pages:
// a 268 MB terrain then takes ~130 page faults on first touch instead of
// ~65000 (where the kernel allows it; otherwise the advice is ignored).
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace ft {

namespace detail {
struct FreeDeleter {
  void operator()(void* p) const noexcept { std::free(p); }
};

inline void* allocate_uninitialised(size_t bytes) {
  constexpr size_t kHuge = size_t(2) << 20;
  const size_t align = bytes >= 2 * kHuge ? kHuge : 64;
  const size_t rounded = (bytes + align - 1) / align * align;
  void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded);
  if (!p) throw std::bad_alloc();
  if (align == kHuge) ::madvise(p, rounded, MADV_HUGEPAGE);
  return p;
}
}  // namespace detail

template <class T>
class Buffer {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>,
                "Buffer holds plain data only");

 public:
  Buffer() = default;
  explicit Buffer(size_t n)
      : data_(static_cast<T*>(detail::allocate_uninitialised(n * sizeof(T)))), size_(n) {}

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
