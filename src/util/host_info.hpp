#pragma once
#include <string>

namespace mssph {

// The host CPU's model name (from /proc/cpuinfo) and core count, e.g. "AMD EPYC 9554 (2 threads)".
std::string host_cpu_name();

// The NVIDIA kernel driver's version line (from /proc/driver/nvidia/version), or "none".
std::string gpu_driver_version();

}  // namespace mssph
