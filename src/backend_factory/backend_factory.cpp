#include "backend_factory/backend_factory.hpp"

#include "cpu/cpu_backend.hpp"
#include "reference_backend.hpp"
#include "util/errors.hpp"
#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

#include <algorithm>

namespace mssph {

const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names{"reference", "cpu", "cuda"};
  return names;
}

std::vector<std::string> float_backend_names() {
  std::vector<std::string> names;
  for (const std::string& name : backend_names()) {
    if (name != "reference") names.push_back(name);
  }
  return names;
}

const std::vector<std::string>& backend_choices() {
  static const std::vector<std::string> choices = [] {
    std::vector<std::string> c = backend_names();
    c.push_back("auto");
    return c;
  }();
  return choices;
}

bool backend_runs_on_gpu(const std::string& name) { return name == "cuda"; }

std::vector<std::string> available_backends() {
  std::vector<std::string> names{"reference", "cpu"};
#ifdef MSSPH_HAVE_CUDA_BACKEND
  names.push_back("cuda");
#endif
  return names;
}

std::vector<GpuDevice> gpu_devices() {
  std::vector<GpuDevice> devices;
#ifdef MSSPH_HAVE_CUDA_BACKEND
  for (const kernels::CudaDeviceInfo& d : kernels::cuda_devices()) {
    devices.push_back({d.index, d.name, d.compute_major, d.compute_minor, d.total_memory, d.multiprocessors});
  }
#endif
  return devices;
}

std::optional<double> gpu_memory_for(const std::string& name) {
  if (!backend_runs_on_gpu(name)) return std::nullopt;
  const std::vector<GpuDevice> devices = gpu_devices();
  if (devices.empty()) return std::nullopt;
  return static_cast<double>(devices.front().total_memory);
}

std::string why_backend_cannot_run(const std::string& name) {
  const std::vector<std::string> built = available_backends();
  if (std::find(built.begin(), built.end(), name) == built.end()) {
    return name == "cuda" ? "this build has no CUDA backend (configured with MSSPH_CUDA=OFF or without nvcc)"
                          : "backend " + name + " is not built";
  }
  if (name == "cuda" && gpu_devices().empty()) return "no CUDA GPU on this machine";
  return "";
}

std::string resolve_backend_name(const std::string& requested) {
  if (requested == "auto") return gpu_devices().empty() ? "cpu" : "cuda";
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

std::optional<std::size_t> backend_device_bytes(const std::string& name, const ParticleSetup& setup) {
#ifdef MSSPH_HAVE_CUDA_BACKEND
  if (name == "cuda") return kernels::cuda_backend_bytes(setup);
#else
  (void)name;
  (void)setup;
#endif
  return std::nullopt;
}

}  // namespace mssph
