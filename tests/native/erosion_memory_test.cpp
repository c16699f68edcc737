// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion's memory is bounded per sample, so a terrain of 16385^2 erodes on a
// 24 GB machine: `fracterra terrain --erode` at 4097^2 peaks at no more than
// 48 bytes a sample (issue 39's bound), the CLI's code, libraries, the
// terrain and its eroded copy included. The peak is the child's own maximum
// resident set (wait4's ru_maxrss), so nothing of the test's own process
// counts. Measured 31.6 bytes a sample at 4097^2 (24.9 at 8193^2, 23.4 at
// 16385^2: the fixed part shrinks per sample). Three doubles a sample more
// (a whole-terrain buffer of that size in landscape()) measured 55.7: fails.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

#ifndef FT_UNDER_ASAN
// The peak resident set of `fracterra args...` in bytes, or -1 if it did not exit 0.
long long peak_bytes_of_cli(const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(FT_CLI_PATH)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1), ::dup2(null, 2);
    ::execv(FT_CLI_PATH, argv.data());
    ::_exit(127);
  }
  int status = 0;
  struct rusage ru {};
  if (pid < 0 || ::wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return (long long)ru.ru_maxrss * 1024;  // Linux reports kilobytes
}
#endif

TEST(ErosionMemory, A4097TerrainErodesInAtMost48BytesASample) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "ASan's shadow memory and quarantine are not the library's memory";
#else
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("ft_erosion_memory_" + std::to_string(::getpid()) + ".npy");
  const long long peak = peak_bytes_of_cli({"terrain", "--method", "midpoint", "--levels", "12", "--seed", "1",
                                            "--erode", "rugged_mountains", "--threads", "2", "--out", out.string()});
  fs::remove(out);
  ASSERT_GT(peak, 0) << "the CLI failed";
  const double samples = 4097.0 * 4097.0;
  EXPECT_LE(double(peak) / samples, 48.0) << "peak " << peak / (1 << 20) << " MiB";
#endif
}

}  // namespace
