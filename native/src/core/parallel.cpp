// SPDX-License-Identifier: GPL-3.0-or-later
// The thread count a call runs on: what was asked, but no more than the
// cores other processes leave free (see parallel.hpp).
#include "core/parallel.hpp"

#include <dirent.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ft {
namespace {

// Runnable tasks on the machine at this instant, the caller included: the
// numerator of /proc/loadavg's fourth field ("4/1234"). -1 if unknown.
int runnable_tasks() {
  FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return -1;
  double l1, l5, l15;
  int running = -1, total;
  if (std::fscanf(f, "%lf %lf %lf %d/%d", &l1, &l5, &l15, &running, &total) != 5) running = -1;
  std::fclose(f);
  return running;
}

// This process's threads that are running or runnable (state R in
// /proc/self/task/*/stat): the caller, and OpenMP workers still spinning
// after the last parallel region. They are not other load.
int own_runnable_threads() {
  DIR* d = opendir("/proc/self/task");
  if (!d) return 1;
  int n = 0;
  char path[64], buf[512];
  while (const dirent* e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    std::snprintf(path, sizeof path, "/proc/self/task/%.20s/stat", e->d_name);
    FILE* f = std::fopen(path, "r");
    if (!f) continue;
    const size_t k = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[k] = '\0';
    // "tid (name) S ...": the state follows the last ')' (a name may hold one).
    const char* close = std::strrchr(buf, ')');
    n += close && close[1] == ' ' && close[2] == 'R';
  }
  closedir(d);
  return std::max(n, 1);
}

}  // namespace

int cores_free_of_other_load() {
  const int cores = omp_get_num_procs();
  const char* ignore = std::getenv("FT_THREADS_IGNORE_LOAD");
  if (ignore && ignore[0] == '1') return cores;
  const int running = runnable_tasks();
  if (running < 0) return cores;
  const int others = std::max(0, running - own_runnable_threads());
  return std::clamp(cores - others, 1, cores);
}

}  // namespace ft
