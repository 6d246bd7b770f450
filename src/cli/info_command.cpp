// `mssph info`: what this binary is and what it can run on.
#include "backend_factory.hpp"
#include "commands.hpp"
#include "util/build_info.hpp"
#include "util/host_info.hpp"

#include <iostream>

namespace mssph::cli {

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
    exit_code = 0;
  });
}

}  // namespace mssph::cli
