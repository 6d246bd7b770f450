#include "backends.hpp"

#include "backend_factory.hpp"
#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace mssph::validation {

std::string why_backend_cannot_run(const std::string& name) {
  if (name != "cuda") {
    const std::vector<std::string> built = available_backends();
    return std::find(built.begin(), built.end(), name) != built.end() ? "" : "backend " + name + " is not built";
  }
#ifdef MSSPH_HAVE_CUDA_BACKEND
  return kernels::cuda_devices().empty() ? "no CUDA GPU on this machine" : "";
#else
  return "this build has no CUDA backend (configured with MSSPH_CUDA=OFF or without nvcc)";
#endif
}

std::string validation_dir() {
  const char* env = std::getenv("MSSPH_VALIDATION_DIR");
  return env && *env ? std::string(env) : std::string(MSSPH_SOURCE_DIR) + "/validation";
}

std::string validation_file(const std::string& relative) { return validation_dir() + "/" + relative; }

}  // namespace mssph::validation
