// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes ft_erode, the boundary the CLI, ctypes and Blender erode through:
// the bytes give a small grid (3..65 samples a side), its heights (raw
// float32, NaN, infinities and 1e38 included, or int16 at a scale from 1e-32
// to 1e31), its world size, the process counts (up to 64 each, so an
// accepted input runs in well under a second) and every rate of
// ft_erosion_params (the default, the default times 1e-8 .. 1e8, or a raw
// double). ft_erode must return a known status with a message; on success
// the eroded terrain (and every map) is finite.
// A hang is a finding twice over: the progress callback is a watchdog that
// cancels after kWatchdogSeconds and then aborts (a step that never reports
// is caught by libFuzzer's -timeout).
// Layout: w, h, flags (1 periodic, 2 raw float heights, 4 maps,
// 8 uplift follows terrain, 16 two threads), fluvial steps, hydraulic and
// thermal passes, one selector byte per rate (then 8 bytes when it asks for a
// raw double), the world size, the height scale, then the heights row by
// row (zeros past the end).
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"
#include "fuzz_util.hpp"

namespace {

using ft::fuzz::bug;
using ft::fuzz::Bytes;

// Far above what an accepted input takes (about 0.2 s for 65 x 65 x 64
// fluvial steps under ASan on a loaded machine).
constexpr double kWatchdogSeconds = 20.0;

struct Watchdog {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  bool fired = false;
};

int32_t watchdog(void* user, double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) bug("progress fraction outside [0, 1]");
  auto* w = static_cast<Watchdog*>(user);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - w->start).count();
  w->fired = s > kWatchdogSeconds;
  return w->fired ? 1 : 0;
}

// 0: the default; 1..127: the default times 10^((s - 64) / 8); 128..255: a raw double.
double rate(Bytes& in, double def) {
  const uint8_t s = in.take<uint8_t>();
  if (s == 0) return def;
  if (s < 128) return (def == 0.0 ? 1e-6 : def) * std::pow(10.0, (int(s) - 64) / 8.0);
  return in.take<double>();
}

void check_status(ft_status s) {
  if (s < FT_OK || s > FT_ERR_INTERNAL) bug("unknown status " + std::to_string(s));
  if (s == FT_ERR_INTERNAL) bug(std::string("FT_ERR_INTERNAL: ") + ft_last_error());
  if (s != FT_OK && ft_last_error()[0] == '\0') bug("a failure without a message");
}

void check_finite(const ft_heightfield* hf, const char* what) {
  const float* z = ft_heightfield_data(hf);
  const size_t n = size_t(ft_heightfield_width(hf)) * size_t(ft_heightfield_height(hf));
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(z[i])) bug(std::string(what) + " holds " + std::to_string(z[i]) + " at " + std::to_string(i));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) { return 0; }

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  const int32_t w = 3 + in.take<uint8_t>() % 63, h = 3 + in.take<uint8_t>() % 63;
  const uint8_t flags = in.take<uint8_t>();
  ft_erosion_params p;
  if (ft_erosion_params_init(&p) != FT_OK) bug("ft_erosion_params_init failed");
  p.periodic = flags & 1;
  p.uplift_follows_terrain = (flags >> 3) & 1;
  p.threads = (flags & 16) ? 2 : 1;
  p.fluvial_steps = in.take<uint8_t>() % 65;
  p.hydraulic_iterations = in.take<uint8_t>() % 65;
  p.thermal_iterations = in.take<uint8_t>() % 65;
  for (double* r : {&p.fluvial_dt, &p.erodibility, &p.area_exponent, &p.diffusion, &p.uplift, &p.hydraulic_dt,
                    &p.rain, &p.evaporation, &p.capacity, &p.dissolve, &p.deposit, &p.talus_degrees, &p.thermal_rate})
    *r = rate(in, *r);
  const uint8_t world = in.take<uint8_t>(), scale_byte = in.take<uint8_t>();
  const double scale = std::pow(10.0, (int(scale_byte) - 128) / 4.0);
  std::vector<float> z(size_t(w) * size_t(h));
  for (float& v : z) v = (flags & 2) ? in.take<float>() : float(in.take<int16_t>() * scale);

  ft_heightfield* hf = nullptr;
  if (ft_heightfield_create(w, h, z.data(), &hf) != FT_OK) bug(std::string("create: ") + ft_last_error());
  if (world != 0) {
    const ft_status s = ft_heightfield_set_world_size(hf, std::pow(10.0, (int(world) - 128) / 8.0));
    check_status(s);
  }
  Watchdog dog;
  p.progress = watchdog;
  p.progress_user = &dog;
  ft_heightfield* out = nullptr;
  ft_heightfield* maps[FT_MAP_COUNT] = {};
  const ft_status s = ft_erode(hf, &p, &out, (flags & 4) ? maps : nullptr);
  if (dog.fired)
    bug("hang: " + std::to_string(w) + " x " + std::to_string(h) + " ran past the watchdog (" +
        std::to_string(kWatchdogSeconds) + " s)");
  check_status(s);
  if (s == FT_OK) {
    if (!out || ft_heightfield_width(out) != w || ft_heightfield_height(out) != h) bug("wrong or missing output");
    check_finite(out, "the eroded terrain");
    if (flags & 4)
      for (auto* m : maps) {
        if (!m) bug("a map is missing");
        check_finite(m, "a map");
      }
  } else if (out) {
    bug("a failure left an output");
  }
  for (auto* m : maps) ft_heightfield_free(m);
  ft_heightfield_free(out);
  ft_heightfield_free(hf);
  return 0;
}
