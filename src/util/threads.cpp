#include "util/threads.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace mssph {
namespace {

int omp_num_threads_from_environment() {
  const char* env = std::getenv("OMP_NUM_THREADS");
  if (!env || !*env) return 0;
  char* end = nullptr;
  const long n = std::strtol(env, &end, 10);  // "4" or the first entry of a list "4,2"
  return end != env && n > 0 && n < 65536 ? static_cast<int>(n) : 0;
}

// Runnable threads averaged over the last minute (/proc/loadavg's first field).
std::optional<double> load_average() {
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  if (in >> load && load >= 0.0) return load;
  return std::nullopt;
}

}  // namespace

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

int free_cpus() {
  const int usable = usable_cpus();
  const std::optional<double> load = load_average();
  if (!load) return usable;
  return std::clamp(usable - static_cast<int>(std::lround(*load)), 1, usable);
}

int default_thread_count() {
  const int from_environment = omp_num_threads_from_environment();
  return from_environment > 0 ? from_environment : free_cpus();
}

std::string default_thread_source() {
  if (omp_num_threads_from_environment() > 0) return "OMP_NUM_THREADS";
  const std::optional<double> load = load_average();
  if (!load) return "usable CPUs";
  char text[96];
  std::snprintf(text, sizeof text, "free CPUs: %d usable, load average %.1f", usable_cpus(), *load);
  return text;
}

void wait_passively_unless_told(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");  // the exec failed: this process keeps the runtime it loaded
}

void set_thread_count(int threads) {
#ifdef _OPENMP
  omp_set_num_threads(std::max(1, threads));
#else
  (void)threads;
#endif
}

}  // namespace mssph
