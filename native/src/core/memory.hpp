// SPDX-License-Identifier: GPL-3.0-or-later
// The documented memory cap: requests are refused with FT_ERR_TOO_LARGE before
// anything is allocated, with the sizes in the message.
#pragma once

#include <cstdint>
#include <string>

namespace ft {

inline constexpr uint64_t kDefaultMemoryCap = uint64_t{8} << 30;  // 8 GiB

uint64_t memory_cap();
void set_memory_cap(uint64_t bytes);  // 0 restores the default
// Bytes the machine can still give (MemAvailable), or UINT64_MAX if unknown.
uint64_t available_memory();
// Throws FT_ERR_TOO_LARGE when `bytes` exceed the cap or the available memory.
void check_allocation(uint64_t bytes, const std::string& what);
// a * b * c with overflow saturating to UINT64_MAX.
uint64_t checked_bytes(uint64_t a, uint64_t b, uint64_t c = 1);

}  // namespace ft
