// SPDX-License-Identifier: GPL-3.0-or-later
// The memory calls of the platform layer (platform.hpp), apart so that
// core/buffer.hpp, which nearly every file includes, stays light.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ft::platform {

// Memory aligned to `align` (a power of two), released by aligned_free.
void* aligned_allocate(size_t align, size_t bytes) noexcept;
void aligned_free(void* p) noexcept;
// Asks for transparent huge pages for a 2 MiB-aligned block (Linux); a no-op
// where the system has no such hint (Windows' large pages need a privilege
// that ordinary users lack).
void advise_huge_pages(void* p, size_t bytes) noexcept;
// Bytes of memory the machine has available now; UINT64_MAX when unknown.
uint64_t available_memory() noexcept;

}  // namespace ft::platform
