// `mssph info`: what this binary is and what it can run on.
#include "backend_factory/backend_factory.hpp"
#include "commands.hpp"
#include "util/build_info.hpp"
#include "util/host_info.hpp"

#include <iostream>

namespace mssph::cli {

namespace {

// One line per visible CUDA device, or why there are none.
void print_gpus() {
  if (!build_info().cuda_backend) {
    std::cout << "  GPUs:         not used (built without the CUDA backend)\n";
    return;
  }
  const std::vector<GpuDevice> devices = gpu_devices();
  if (devices.empty()) std::cout << "  GPUs:         none visible (no CUDA driver or device)\n";
  for (const GpuDevice& d : devices) {
    std::cout << "  GPU " << d.index << ":        " << d.name << ", compute capability " << d.compute_major << "."
              << d.compute_minor << ", " << d.multiprocessors << " multiprocessors, " << d.total_memory / (1024 * 1024)
              << " MiB\n";
  }
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  CLI::App* info = app.add_subcommand("info", "Print version, build options, backends and devices");
  info->callback([&exit_code] {
    const BuildInfo& b = build_info();
    std::cout << "mssph " << b.version << "\n"
              << "  git commit:   " << b.git_commit << "\n"
              << "  build type:   " << b.build_type << "\n"
              << "  compiler:     " << b.compiler << "\n"
              << "  CUDA backend: " << (b.cuda_backend ? "built for sm_" + b.cuda_architectures : "not built") << "\n"
              << "  host:         " << host_cpu_name() << "\n"
              << "  backends:    ";
    for (const std::string& name : available_backends()) std::cout << " " << name;
    std::cout << "\n";
    print_gpus();
    exit_code = 0;
  });
}

}  // namespace mssph::cli
