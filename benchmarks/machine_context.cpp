// The machine and build recorded in every benchmark file's context. `mssph bench compare` refuses
// files whose mssph_cpu, mssph_gpu or mssph_build_type differ (src/bench/benchmark_results.hpp).
#include "backend_factory/backend_factory.hpp"
#include "benchmark_suite.hpp"
#include "step_delay.hpp"
#include "util/build_info.hpp"
#include "util/host_info.hpp"

#include <benchmark/benchmark.h>

#include <fstream>
#include <string>
#include <thread>

namespace mssph::bench {
namespace {

// The GPU the cuda backend runs on (device 0), or "none": a property of the machine, the same
// whether this binary was built with the CUDA backend or not (mssph_cuda_backend says that).
std::string gpu_name() {
  const std::vector<GpuDevice> devices = gpu_devices();
  if (devices.empty()) return "none";
  const GpuDevice& d = devices.front();
  return d.name + " (sm_" + std::to_string(d.compute_major) + std::to_string(d.compute_minor) + ", " +
         std::to_string(d.total_memory / (1024 * 1024)) + " MiB)";
}

// The NVIDIA kernel driver's version line, as nvidia-smi reports it; "none" without the driver.
std::string gpu_driver() {
  std::ifstream in("/proc/driver/nvidia/version");
  std::string line;
  if (!in || !std::getline(in, line)) return "none";
  return line;
}

}  // namespace

void add_machine_context() {
  const BuildInfo& b = build_info();
  benchmark::AddCustomContext("mssph_version", b.version);
  benchmark::AddCustomContext("mssph_git_commit", b.git_commit);
  benchmark::AddCustomContext("mssph_build_type", b.build_type);
  benchmark::AddCustomContext("mssph_compiler", b.compiler);
  benchmark::AddCustomContext("mssph_cpu", host_cpu_name());
  benchmark::AddCustomContext("mssph_cpu_cores", std::to_string(std::thread::hardware_concurrency()));
  benchmark::AddCustomContext("mssph_gpu", gpu_name());
  benchmark::AddCustomContext("mssph_cuda_backend",
                              b.cuda_backend ? "built for sm_" + b.cuda_architectures : "not built");
  benchmark::AddCustomContext("mssph_gpu_driver", gpu_driver());
  const double delay = step_delay_seconds();
  if (delay > 0.0) {
    benchmark::AddCustomContext("mssph_test_step_delay_us",
                                std::to_string(delay * 1e6) + " (test hook: not a real measurement)");
  }
  if (const std::size_t every = extra_step_interval(); every != 0) {
    benchmark::AddCustomContext("mssph_test_extra_step_every",
                                std::to_string(every) + " (test hook: not a real measurement)");
  }
}

}  // namespace mssph::bench
