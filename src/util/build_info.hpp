#pragma once
// What this binary is: recorded in every run log and printed by `mssph info`.
#include <string>

namespace mssph {

struct BuildInfo {
  std::string version;     // project version, e.g. "0.1.0"
  std::string git_commit;  // `git describe --always --dirty` at build time
  std::string build_type;  // CMake build type
  std::string compiler;    // host compiler and version
  bool cuda_backend;       // built with the CUDA backend
  std::string cuda_architectures;
};

const BuildInfo& build_info();

}  // namespace mssph
