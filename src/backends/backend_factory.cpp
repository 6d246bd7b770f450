#include "backends/backend_factory.hpp"

#include "cpu/cpu_backend.hpp"
#include "reference_backend.hpp"
#include "util/errors.hpp"
#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

#include <algorithm>

namespace mssph {
namespace {

bool cuda_device_present() {
#ifdef MSSPH_HAVE_CUDA_BACKEND
  return !kernels::cuda_devices().empty();
#else
  return false;
#endif
}

}  // namespace

std::vector<std::string> available_backends() {
  std::vector<std::string> names{"reference", "cpu"};
#ifdef MSSPH_HAVE_CUDA_BACKEND
  names.push_back("cuda");
#endif
  return names;
}

std::string resolve_backend_name(const std::string& requested) {
  if (requested == "auto") return cuda_device_present() ? "cuda" : "cpu";
  const std::vector<std::string> available = available_backends();
  if (std::find(available.begin(), available.end(), requested) == available.end()) {
    throw InputError("--backend " + requested + ": this build of mssph has no " + requested +
                     " backend (built without CUDA; available: reference, cpu)");
  }
  return requested;
}

std::unique_ptr<Backend> make_backend(const std::string& name, ParticleSetup setup) {
  if (name == "reference") return std::make_unique<reference::ReferenceBackend>(std::move(setup));
  if (name == "cpu") return std::make_unique<kernels::CpuBackend>(std::move(setup));
#ifdef MSSPH_HAVE_CUDA_BACKEND
  if (name == "cuda") return kernels::make_cuda_backend(std::move(setup));
#endif
  throw InputError("unknown backend \"" + name + "\"");
}

}  // namespace mssph
