// SPDX-License-Identifier: GPL-3.0-or-later
// A hang is impossible to miss: every erosion preset, fitted as the CLI and
// the add-on fit it, erodes generated terrains over many seeds and sizes
// under a watchdog. Issue 24's hang (a loop in the pit fills on 4 of 9 seeds
// at one size) showed that one terrain per test is not enough.
// The watchdog has two parts:
//  - the progress callback cancels once a run passes kDeadlineSeconds (a run
//    that keeps reporting but never ends); the test then fails naming the
//    preset, the landform, the size and the seed;
//  - a step that never returns never reports: a monitor thread then prints
//    the same names and aborts the test program, so ctest shows the culprit
//    instead of timing out silently.
// A normal run takes 1-250 ms here (Release); the deadline allows for
// sanitizer builds and a loaded machine. No timing is asserted otherwise.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "sanitizer.hpp"
#include "test_terrains.hpp"

namespace ft::erosion {
namespace {

constexpr double kDeadlineSeconds = 60.0;
// The monitor waits longer than the callback's deadline, so a run that still
// reports is failed by the callback (cleanly), not aborted.
constexpr double kAbortSeconds = 2 * kDeadlineSeconds;

using Clock = std::chrono::steady_clock;

struct Deadline {
  Clock::time_point end;
  static int32_t check(void* self, double) { return Clock::now() > static_cast<Deadline*>(self)->end ? 1 : 0; }
};

// Aborts the program with `what` if `finish` is not called within kAbortSeconds.
class Monitor {
 public:
  explicit Monitor(std::string what) : what_(std::move(what)), thread_([this] { watch(); }) {}
  ~Monitor() {
    {
      std::lock_guard<std::mutex> lock(m_);
      done_ = true;
    }
    cv_.notify_one();
    thread_.join();
  }

 private:
  void watch() {
    std::unique_lock<std::mutex> lock(m_);
    if (!cv_.wait_for(lock, std::chrono::duration<double>(kAbortSeconds), [this] { return done_; })) {
      std::fprintf(stderr, "HANG: %s did not return within %.0f s (a step that never reports progress)\n",
                   what_.c_str(), kAbortSeconds);
      std::fflush(stderr);
      std::abort();
    }
  }
  std::string what_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

// The add-on's default landform (levelled, raised, a radial falloff to the
// edge level: the plain that issue 24's hang wore down to subnormal heights)
// on the midpoint method, or plain fBm.
Heightfield terrain(bool landform, int32_t levels, uint64_t seed) {
  return landform ? test::default_mountain(levels, seed) : test::fbm_terrain((1 << levels) + 1, seed);
}

void erode_under_watchdog(const std::string& preset, bool landform, int32_t levels, uint64_t seed) {
  const Heightfield hf = terrain(landform, levels, seed);
  const std::string what = "preset " + preset + " on the " + (landform ? "default landform" : "fBm terrain") +
                           " of " + std::to_string(hf.width()) + "^2 samples, seed " + std::to_string(seed);
  ErosionConfig c = erosion_preset(preset, hf);
  Deadline deadline{Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(kDeadlineSeconds))};
  c.progress = Progress(&Deadline::check, &deadline);
  Monitor monitor(what);
  try {
    const Heightfield out = erode(hf, c, nullptr);
    ASSERT_EQ(out.size(), hf.size()) << what;
  } catch (const Error& e) {
    if (e.status() == FT_ERR_CANCELLED)
      ADD_FAILURE() << "HANG: " << what << " ran past the watchdog's " << kDeadlineSeconds << " s";
    else
      ADD_FAILURE() << what << ": " << e.what();
  }
}

// 33^2 to 257^2, more seeds where runs are cheap: (16 + 12 + 8 + 3) seeds
// x 2 terrains for each preset.
struct SizeSeeds {
  int32_t levels, seeds;
};
#ifdef FT_UNDER_ASAN
// Under ASan (about 10x slower) the small sizes only: a hang is size-blind.
constexpr SizeSeeds kRuns[] = {{5, 6}, {6, 3}};
#else
constexpr SizeSeeds kRuns[] = {{5, 16}, {6, 12}, {7, 8}, {8, 3}};
#endif

// One test per preset (its own ctest entry, so ctest -j spreads them):
// ErosionWatchdog/EveryPreset.NAME/PRESET.
class EveryPreset : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(ErosionWatchdog, EveryPreset, ::testing::ValuesIn(erosion_preset_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(EveryPreset, FinishesOnTheDefaultLandformOverSeedsAndSizes) {
  for (const auto [levels, seeds] : kRuns)
    for (int s = 1; s <= seeds; ++s) erode_under_watchdog(GetParam(), true, levels, uint64_t(s));
}

TEST_P(EveryPreset, FinishesOnFbmTerrainsOverSeedsAndSizes) {
  for (const auto [levels, seeds] : kRuns)
    for (int s = 1; s <= seeds; ++s) erode_under_watchdog(GetParam(), false, levels, uint64_t(s));
}

}  // namespace
}  // namespace ft::erosion
