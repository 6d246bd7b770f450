#include "backends.hpp"

#include "backends/backend_factory.hpp"
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

#include "config/scene_loader.hpp"

#include <cstdio>

namespace mssph::validation {

Scene case_scene(const std::string& folder, const std::vector<std::string>& overrides) {
  return load_scene(validation_file(folder + "/scene.json"), overrides);
}

std::string exact(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::vector<std::string> resolution_overrides(const Scene& scene, double dx) {
  const double dt = scene.simulation.dt * dx / scene.simulation.particle_spacing;
  return {"simulation/particle_spacing=" + exact(dx), "simulation/dt=" + exact(dt)};
}

}  // namespace mssph::validation
