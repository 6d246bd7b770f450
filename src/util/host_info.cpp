#include "util/host_info.hpp"

#include <fstream>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace mssph {

std::string host_cpu_name() {
  std::string model = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) model = line.substr(line.find_first_not_of(' ', colon + 1));
      break;
    }
  }
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
#else
  const int threads = 1;
#endif
  return model + " (" + std::to_string(threads) + " threads)";
}

std::string gpu_driver_version() {
  std::ifstream version("/proc/driver/nvidia/version");
  std::string line;
  if (!std::getline(version, line)) return "none";
  // "NVRM version: NVIDIA UNIX x86_64 Kernel Module  550.54.15  Tue Mar  5 ..." -> from "Kernel Module" on.
  const auto module = line.find("Kernel Module");
  return module == std::string::npos ? line : line.substr(module);
}

}  // namespace mssph
