// SPDX-License-Identifier: GPL-3.0-or-later
// Hardening through the C ABI, as ctypes sees it: the memory cap refuses
// sizes before allocating (with the size in the message), an allocation that
// fails anyway is FT_ERR_OUT_OF_MEMORY, progress reports come often enough to
// cancel a long call promptly, and a cancelled call hands back nothing.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cstring>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"
#include "sanitizer.hpp"

namespace {

struct Recorder {
  std::vector<double> fractions;
  int cancel_at = -1;  // report index that cancels; -1: never
};

int32_t record(void* user, double fraction) {
  auto* r = static_cast<Recorder*>(user);
  r->fractions.push_back(fraction);
  return int(r->fractions.size()) - 1 == r->cancel_at ? 1 : 0;
}

ft_terrain_params terrain(int levels, int method = FT_TERRAIN_MIDPOINT) {
  ft_terrain_params p;
  EXPECT_EQ(ft_terrain_params_init(&p), FT_OK);
  p.levels = levels;
  p.method = method;
  p.threads = 1;  // the machine running the tests is shared
  return p;
}

class MemoryCap : public ::testing::Test {
 protected:
  void TearDown() override { ft_set_memory_cap(0); }
};

TEST_F(MemoryCap, TerrainAboveTheCapIsRefusedWithTheSize) {
  ft_set_memory_cap(uint64_t(32) << 20);
  ft_terrain_params p = terrain(12);  // 4097^2 floats = 64.03 MiB
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_TOO_LARGE);
  EXPECT_EQ(hf, nullptr);
  const std::string msg = ft_last_error();
  EXPECT_NE(msg.find("needs 64.03 MiB"), std::string::npos) << msg;
  EXPECT_NE(msg.find("memory cap of 32.00 MiB"), std::string::npos) << msg;
  p.levels = 11;  // 16.02 MiB fits
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  ft_heightfield_free(hf);
}

TEST_F(MemoryCap, DefaultIsEightGiBAndZeroRestoresIt) {
  EXPECT_EQ(ft_memory_cap(), uint64_t(8) << 30);
  ft_set_memory_cap(1234);
  EXPECT_EQ(ft_memory_cap(), 1234u);
  ft_set_memory_cap(0);
  EXPECT_EQ(ft_memory_cap(), uint64_t(8) << 30);
}

TEST_F(MemoryCap, HeightfieldCreateAboveTheCapIsRefused) {
  ft_set_memory_cap(1 << 20);
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_heightfield_create(1024, 1024, nullptr, &hf), FT_ERR_TOO_LARGE);  // 4 MiB
  EXPECT_EQ(hf, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("needs 4.00 MiB"), std::string::npos) << ft_last_error();
}


TEST(OutOfMemory, FailedAllocationIsAStatusNotAnAbort) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "ASan reserves terabytes of address space: no address-space limit possible";
#else
  // 1.5 GiB passes the cap but not an address-space limit 256 MiB above
  // what the process maps now: the allocation itself fails.
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &old), 0);
  FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  ASSERT_EQ(std::fscanf(f, "%lu", &pages), 1);
  std::fclose(f);
  const rlim_t limit = rlim_t(pages) * 4096 + (rlim_t(256) << 20);
  const rlimit tight{limit, old.rlim_max};
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  ft_heightfield* hf = nullptr;
  const ft_status s = ft_heightfield_create(20000, 20000, nullptr, &hf);
  setrlimit(RLIMIT_AS, &old);
  EXPECT_EQ(s, FT_ERR_OUT_OF_MEMORY) << ft_last_error();
  EXPECT_EQ(hf, nullptr);
  EXPECT_STRNE(ft_last_error(), "");
#endif
}

class Cancel : public ::testing::TestWithParam<int> {};

TEST_P(Cancel, ReportsAreFrequentMonotoneAndEndAtOne) {
  // Reports come at least every 2^20 samples visited (a band), so for levels
  // 11 the fraction never jumps by more than 2^20 / 2049^2 = 0.25; without
  // bands the last stage alone was 3/4 of the work in one jump.
  Recorder r;
  ft_terrain_params p = terrain(11, GetParam());
  p.progress = record;
  p.progress_user = &r;
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  ASSERT_GE(r.fractions.size(), 8u);
  EXPECT_EQ(r.fractions.back(), 1.0);
  double prev = 0, max_jump = 0;
  for (double f : r.fractions) {
    EXPECT_GE(f, prev);
    EXPECT_LE(f, 1.0);
    max_jump = std::max(max_jump, f - prev);
    prev = f;
  }
  EXPECT_LE(max_jump, double(1 << 20) / (2049.0 * 2049.0));

  // The reports change nothing: same bits as a run without a callback.
  ft_terrain_params q = terrain(11, GetParam());
  ft_heightfield* plain = nullptr;
  ASSERT_EQ(ft_terrain_generate(&q, &plain), FT_OK);
  EXPECT_EQ(std::memcmp(ft_heightfield_data(hf), ft_heightfield_data(plain), sizeof(float) * 2049 * 2049), 0);
  ft_heightfield_free(hf);
  ft_heightfield_free(plain);
}

TEST_P(Cancel, AtAnyReportReturnsCancelledAndNoHandle) {
  Recorder all;
  ft_terrain_params p = terrain(7, GetParam());
  p.progress = record;
  p.progress_user = &all;
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK);
  ft_heightfield_free(hf);
  for (int k = 0; k < int(all.fractions.size()); ++k) {
    Recorder r;
    r.cancel_at = k;
    p.progress_user = &r;
    hf = reinterpret_cast<ft_heightfield*>(&r);  // must be reset to NULL
    EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_CANCELLED) << "report " << k;
    EXPECT_EQ(hf, nullptr);
    EXPECT_EQ(int(r.fractions.size()), k + 1) << "no report after the cancel";
    EXPECT_NE(std::string(ft_last_error()).find("cancelled"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, Cancel, ::testing::Values(FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS));

TEST(CancelProfile, ReportsEveryMillionSamplesAndCancels) {
  // Levels 22: 2^22 midpoints in total, 2^21 in the last step: reported in
  // bands of 2^20, so at least 4 reports and none jumping more than 1/4.
  ft_profile_params p;
  ASSERT_EQ(ft_profile_params_init(&p), FT_OK);
  p.levels = 22;
  Recorder r;
  p.progress = record;
  p.progress_user = &r;
  std::vector<float> x(size_t(ft_profile_length(p.levels))), plain(x.size());
  ASSERT_EQ(ft_profile_generate(&p, x.data(), x.size()), FT_OK);
  ASSERT_GE(r.fractions.size(), 4u);
  double prev = 0;
  for (double f : r.fractions) {
    EXPECT_LE(f - prev, 0.25 * (1 + 1e-6));  // 2^20 / (2^22 - 1)
    EXPECT_GE(f, prev);
    prev = f;
  }
  EXPECT_EQ(r.fractions.back(), 1.0);
  ft_profile_params q = p;
  q.progress = nullptr;
  ASSERT_EQ(ft_profile_generate(&q, plain.data(), plain.size()), FT_OK);
  EXPECT_EQ(x, plain) << "reports change the profile";

  Recorder c;
  c.cancel_at = 1;
  p.progress_user = &c;
  EXPECT_EQ(ft_profile_generate(&p, x.data(), x.size()), FT_ERR_CANCELLED);
  EXPECT_EQ(c.fractions.size(), 2u);
}

}  // namespace
