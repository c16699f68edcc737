// SPDX-License-Identifier: GPL-3.0-or-later
// The core layer: counter-based randomness, memory cap, atomic files.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>
#include <omp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.hpp"
#include "core/heightfield.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/parallel_rows.hpp"
#include "core/platform.hpp"
#include "core/rng.hpp"
#include "io/atomic_file.hpp"

namespace ft {
namespace {

TEST(Rng, BatchFillMatchesRandom123Philox) {
  // The vectorised batch path must give Random123's Philox4x32-10 bits.
  const uint64_t seed = 0x0123456789abcdefULL;
  const Counter c{17, 3, Stream::kTerrainSquare};
  std::vector<float> u(1000);
  uniform_fill(seed, c, 5, u.size(), u.data());
  for (size_t i = 0; i < u.size(); ++i) {
    const uint32_t bits = random_bits(seed, c, 5 + i);
    ASSERT_EQ(u[i], bits_to_unit_open(bits)) << "index " << i;
  }
}

TEST(Rng, GaussianFillIsAddressableByIndex) {
  const Counter c{2, 9, Stream::kTerrainDiamond};
  std::vector<float> all(300), part(100);
  gaussian_fill(7, c, 0, all.size(), all.data());
  gaussian_fill(7, c, 101, part.size(), part.data());  // unaligned start
  for (size_t i = 0; i < part.size(); ++i) ASSERT_EQ(part[i], all[101 + i]);
  for (size_t i = 0; i < 50; ++i) ASSERT_EQ(gaussian_at(7, c, i), all[i]);
}

TEST(Rng, GaussianMomentsMatchStandardNormal) {
  // n = 4e6 draws: the standard error of the mean is 1/sqrt(n) = 5e-4, of the
  // variance sqrt(2/n) = 7e-4, of the 4th moment sqrt(96/n) = 4.9e-3.
  // Tolerances are 5 standard errors.
  const size_t n = 4'000'000;
  std::vector<float> g(n);
  gaussian_fill(42, Counter{0, 0, Stream::kFirstUser}, 0, n, g.data());
  double m1 = 0, m2 = 0, m4 = 0;
  size_t beyond3 = 0;
  for (float v : g) {
    m1 += v;
    m2 += double(v) * v;
    m4 += double(v) * v * v * v;
    beyond3 += std::fabs(v) > 3.0f;
  }
  m1 /= n, m2 /= n, m4 /= n;
  EXPECT_NEAR(m1, 0.0, 2.5e-3);
  EXPECT_NEAR(m2, 1.0, 3.5e-3);
  EXPECT_NEAR(m4, 3.0, 2.5e-2);
  // P(|g| > 3) = 0.0027: 10800 expected, sd ~104.
  EXPECT_NEAR(double(beyond3), 0.0027 * n, 520.0);
}

TEST(Rng, DifferentSeedsAndStreamsDiffer) {
  EXPECT_NE(gaussian_at(1, Counter{0, 0, Stream::kTerrainSquare}, 0),
            gaussian_at(2, Counter{0, 0, Stream::kTerrainSquare}, 0));
  EXPECT_NE(gaussian_at(1, Counter{0, 0, Stream::kTerrainSquare}, 0),
            gaussian_at(1, Counter{0, 0, Stream::kTerrainDiamond}, 0));
}

TEST(Memory, RefusesAllocationAboveCapWithSizeInMessage) {
  set_memory_cap(1 << 20);
  try {
    check_allocation(2 << 20, "a test buffer");
    FAIL() << "expected FT_ERR_TOO_LARGE";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_TOO_LARGE);
    EXPECT_NE(std::string(e.what()).find("a test buffer needs"), std::string::npos) << e.what();
  }
  set_memory_cap(0);
  EXPECT_EQ(memory_cap(), kDefaultMemoryCap);
}

TEST(AtomicFile, UncommittedWriteLeavesOldFileIntact) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_atomic_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "f.txt").string();
  io::write_file_atomically(path, "old");
  {
    io::AtomicFile f(path);
    f.write("new but never committed");
  }  // destroyed without commit, as when a writer throws midway
  EXPECT_EQ(io::read_file(path), "old");
  size_t files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "the temporary file must be removed";
  std::filesystem::remove_all(dir);
}

TEST(Platform, PathArithmeticKeepsUtf8Names) {
  // The helpers that replace std::filesystem::path(std::string): on Linux
  // the same strings as before; under Wine windows_cli_unicode_path checks
  // the Windows side (where std::filesystem::path(std::string) mangled them).
  EXPECT_EQ(platform::join_path("Dossier été", "planète"), "Dossier été/planète");
  EXPECT_EQ(platform::join_path("out/", "unity"), "out/unity");
  EXPECT_EQ(platform::join_path("", "face_px.png"), "face_px.png");
  EXPECT_EQ(platform::file_name_of("Dossier été/carrés"), "carrés");
  EXPECT_EQ(platform::sibling_path("Dossier été/globe.pov", "_height.png"), "Dossier été/globe_height.png");
  EXPECT_EQ(platform::sibling_path("splat.png", "_1.png"), "splat_1.png");
}

TEST(AtomicFile, MissingFolderIsAClearIoError) {
  try {
    io::write_file_atomically("/nonexistent-folder-ft/x.png", "x");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_IO);
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
}

}  // namespace
}  // namespace ft

namespace ft {
namespace {
using detail::dispatch_path;
using detail::gaussian_fill_on_path;
using detail::rng_path_available;
using detail::RngPath;
using detail::uniform_fill_on_path;

TEST(Rng, AllDispatchPathsGiveTheSameBits) {
  // Every path against baseline x86-64, bit for bit: heads that start inside
  // a block (first % 4 != 0), lengths that end inside one and inside a batch
  // (the AVX2 path's 64 blocks, AVX-512's 16), counters that wrap past 2^32
  // blocks, and the uniform fill too. A path this CPU lacks is skipped (say
  // which: CI on an older machine would test fewer).
  const struct { uint64_t seed; Counter c; uint64_t first; size_t n; } cases[] = {
      {99, {5, 6, Stream::kTerrainSquare}, 3, 10001},
      {0xfedcba9876543210ULL, {0, 13, Stream::kTerrainDiamond}, 0, 4096},
      {1, {8191, 1, Stream::kTerrainCorners}, 0, 4},
      {2, {7, 2, Stream::kNoise}, 1, 2},
      {3, {7, 2, Stream::kNoise}, 2, 63},
      {4, {1, 14, Stream::kFirstUser}, 5, 65},
      {5, {4097, 13, Stream::kTerrainSquare}, 61, 259},
      {6, {3, 3, Stream::kTerrainAddNew}, (uint64_t(1) << 34) - 30, 100},  // block counter wraps
  };
  for (const RngPath path : {RngPath::kAvx2, RngPath::kAvx512}) {
    if (!rng_path_available(path)) {
      std::printf("[ skipped ] path %d: not on this CPU\n", int(path));
      continue;
    }
    for (const auto& k : cases) {
      for (const bool gaussian : {true, false}) {
        std::vector<float> a(k.n + 1, -7.0f), b(k.n + 1, -7.0f);  // the last one must stay untouched
        (gaussian ? gaussian_fill_on_path : uniform_fill_on_path)(path, k.seed, k.c, k.first, k.n, a.data());
        (gaussian ? gaussian_fill_on_path : uniform_fill_on_path)(RngPath::kBaseline, k.seed, k.c, k.first, k.n,
                                                                  b.data());
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
            << "path " << int(path) << (gaussian ? " gaussian" : " uniform") << " first " << k.first << " n " << k.n;
        EXPECT_EQ(a[k.n], -7.0f);
      }
    }
  }
}

TEST(Rng, UnitIsAScaledOddInteger) {
  // rng_avx512.cpp relies on bits_to_unit_open(bits) == float(2 (bits >> 8) + 1) / 2^25
  // (one rounding of the same number either way): every one of the 2^24 values.
  for (uint32_t k = 0; k < (1u << 24); ++k) {
    const float a = bits_to_unit_open(k << 8), b = float(2 * k + 1) * 0x1p-25f;
    if (std::bit_cast<uint32_t>(a) != std::bit_cast<uint32_t>(b)) FAIL() << "k " << k << ": " << a << " != " << b;
  }
}

TEST(Rng, DispatchTakesTheFastestPathTheCpuHas) {
  // So that the benchmarks measure what users run (FT_DISPATCH unset here).
  const char* expected = rng_path_available(RngPath::kAvx512) ? "avx512"
                         : rng_path_available(RngPath::kAvx2) ? "avx2"
                                                              : "baseline";
  if (!std::getenv("FT_DISPATCH")) {
    EXPECT_STREQ(dispatch_path(), expected);
  }
}
}  // namespace
}  // namespace ft

namespace ft {
namespace {

// Issue 25: on a busy machine a team of OpenMP threads loses to one. With
// a busy process per core running, other processes leave no core free, so
// a call takes one thread whatever it asked (other load only adds to it);
// the override gives every core back.
TEST(ForRows, ReportsAtMostAbout128TimesInOrderAndEndsAtOne) {
  // Each report may be a call into a script (Blender's progress bar): a
  // report per row cost a 1025-row colour map 40 ms. 128 reports, one per
  // ceil(count / 128) rows, and the final 1.
  for (const int threads : {1, 2}) {
    for (const int64_t count : {int64_t(1), int64_t(100), int64_t(1025), int64_t(100000)}) {
      std::vector<double> seen;
      std::vector<int> rows(size_t(count), 0);
      for_rows(count, threads, Progress([](void* u, double f) {
        static_cast<std::vector<double>*>(u)->push_back(f);
        return 0;
      }, &seen), [&](int64_t k) { rows[size_t(k)] += 1; });
      for (int r : rows) ASSERT_EQ(r, 1);
      ASSERT_FALSE(seen.empty());
      EXPECT_EQ(seen.back(), 1.0);
      EXPECT_LE(seen.size(), size_t(std::min<int64_t>(count, 128) + 1)) << count << " rows, " << threads;
      for (size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1], seen[i]);
      if (threads == 1 && count >= 128) {
        EXPECT_GE(seen.size(), size_t(100)) << "the bar still moves";
      }
    }
  }
}

TEST(ForRows, ACancelStopsTheRestOfTheRows) {
  std::atomic<int64_t> ran{0};
  EXPECT_THROW(for_rows(100000, 1, Progress([](void*, double) { return 1; }, nullptr),
                        [&](int64_t) { ran.fetch_add(1); }),
               Error);
  EXPECT_LE(ran.load(), 100000 / 128 + 1);  // stopped at the first report
}

TEST(OrderedSum, TheSameBitsOnOneAndTwoThreadsAsAStatsMean) {
  // Values of mixed magnitude, whose float sum depends on the order; the
  // heightfield's stats take the team the load leaves, so both team sizes
  // are forced.
  Heightfield hf(1000, 700);
  for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(std::sin(double(i)) * std::pow(10.0, double(i % 7)));
  const auto sum = [&](int team) {
    return ordered_sum(int64_t(hf.size()), team, [&](int64_t i) { return double(hf.data()[i]); });
  };
  EXPECT_EQ(sum(1), sum(2));
  EXPECT_EQ(sum(1), sum(3));
  ::setenv("FT_THREADS_IGNORE_LOAD", "1", 1);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const HeightStats one = hf.stats();
  omp_set_num_threads(2);
  const HeightStats two = hf.stats();
  omp_set_num_threads(saved);
  EXPECT_EQ(one.mean, two.mean);
  EXPECT_EQ(one.std, two.std);
}

TEST(Threads, ABusyMachineGetsOneThreadAndTheOverrideAllCores) {
  const int cores = omp_get_num_procs();
  std::vector<pid_t> busy;
  for (int c = 0; c < cores; ++c) {
    const pid_t pid = fork();
    if (pid == 0)
      for (;;) asm volatile("");  // a busy loop the compiler keeps
    ASSERT_GT(pid, 0);
    busy.push_back(pid);
  }
  ::unsetenv("FT_THREADS_IGNORE_LOAD");
  // The children are runnable as soon as they exist; a few samples ride
  // out an instant when the kernel has one of them mid-switch.
  int free_cores = cores;
  for (int k = 0; k < 20 && free_cores > 1; ++k) free_cores = cores_free_of_other_load();
  EXPECT_EQ(free_cores, 1);
  EXPECT_EQ(resolve_threads(0), 1);
  EXPECT_EQ(resolve_threads(2), 1);
  ::setenv("FT_THREADS_IGNORE_LOAD", "1", 1);
  EXPECT_EQ(cores_free_of_other_load(), cores);
  EXPECT_EQ(resolve_threads(1), 1);
  for (const pid_t pid : busy) kill(pid, SIGKILL), waitpid(pid, nullptr, 0);
}

}  // namespace
}  // namespace ft
