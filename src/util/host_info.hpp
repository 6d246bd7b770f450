#pragma once
#include <string>

namespace mssph {

// The host CPU's model name (from /proc/cpuinfo) and core count, e.g. "AMD EPYC 9554 (2 threads)".
std::string host_cpu_name();

}  // namespace mssph
