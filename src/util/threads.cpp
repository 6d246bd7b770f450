#include "util/threads.hpp"

#include <sched.h>

#include <algorithm>
#include <cstdlib>

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

}  // namespace

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

int default_thread_count() {
  const int from_environment = omp_num_threads_from_environment();
  return from_environment > 0 ? from_environment : usable_cpus();
}

std::string default_thread_source() {
  return omp_num_threads_from_environment() > 0 ? "OMP_NUM_THREADS" : "usable CPUs";
}

void set_thread_count(int threads) {
#ifdef _OPENMP
  omp_set_num_threads(std::max(1, threads));
#else
  (void)threads;
#endif
}

}  // namespace mssph
