// The core layer: counter-based randomness, memory cap, atomic files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>
#include <unistd.h>

#include "core/error.hpp"
#include "core/memory.hpp"
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
  write_file_atomically(path, "old");
  {
    AtomicFile f(path);
    f.write("new but never committed");
  }  // destroyed without commit, as when a writer throws midway
  EXPECT_EQ(read_file(path), "old");
  size_t files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "the temporary file must be removed";
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, MissingFolderIsAClearIoError) {
  try {
    write_file_atomically("/nonexistent-folder-ft/x.png", "x");
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
TEST(Rng, AllDispatchPathsGiveTheSameBits) {
  const Counter c{5, 6, Stream::kTerrainSquare};
  std::vector<float> a(10001), b(10001);
  detail::gaussian_fill_on_path(true, 99, c, 3, a.size(), a.data());
  detail::gaussian_fill_on_path(false, 99, c, 3, b.size(), b.data());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << "path " << detail::dispatch_path();
}
}  // namespace
}  // namespace ft
