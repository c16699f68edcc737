// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/memory.hpp"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/error.hpp"
#include "core/platform_memory.hpp"

namespace ft {
namespace {
std::atomic<uint64_t> g_cap{kDefaultMemoryCap};

std::string human(uint64_t bytes) {
  char buf[64];
  if (bytes == std::numeric_limits<uint64_t>::max()) return "more than 16 EiB";
  if (bytes >= uint64_t{1} << 30)
    std::snprintf(buf, sizeof buf, "%.2f GiB", double(bytes) / double(uint64_t{1} << 30));
  else if (bytes >= uint64_t{1} << 20)
    std::snprintf(buf, sizeof buf, "%.2f MiB", double(bytes) / double(uint64_t{1} << 20));
  else
    std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  return buf;
}
}  // namespace

uint64_t memory_cap() { return g_cap.load(); }
void set_memory_cap(uint64_t bytes) { g_cap.store(bytes == 0 ? kDefaultMemoryCap : bytes); }

uint64_t available_memory() { return platform::available_memory(); }

uint64_t checked_bytes(uint64_t a, uint64_t b, uint64_t c) {
  constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
  if (a != 0 && b > kMax / a) return kMax;
  uint64_t ab = a * b;
  if (ab != 0 && c > kMax / ab) return kMax;
  return ab * c;
}

void check_allocation(uint64_t bytes, const std::string& what) {
  uint64_t cap = memory_cap();
  if (bytes > cap)
    fail(FT_ERR_TOO_LARGE, what + " needs " + human(bytes) + ", above the memory cap of " +
                               human(cap) + " (ft_set_memory_cap changes it)");
  uint64_t avail = available_memory();
  if (bytes > avail)
    fail(FT_ERR_TOO_LARGE, what + " needs " + human(bytes) + " but the machine has only " +
                               human(avail) + " available");
}

}  // namespace ft
