#include "backends.hpp"

#include "config/scene_loader.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace mssph::validation {

std::string validation_dir() {
  const char* env = std::getenv("MSSPH_VALIDATION_DIR");
  return env && *env ? std::string(env) : std::string(MSSPH_SOURCE_DIR) + "/validation";
}

std::string validation_file(const std::string& relative) { return validation_dir() + "/" + relative; }

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

std::vector<std::string> viscous_resolution_overrides(const Scene& scene, double dx, double rest_density,
                                                      double viscosity) {
  const double h = 2.0 * dx;
  const double viscous_dt = 0.8 * 0.125 * h * h * rest_density / viscosity;
  const double dt = std::min(scene.simulation.dt * dx / scene.simulation.particle_spacing, viscous_dt);
  return {"simulation/particle_spacing=" + exact(dx), "simulation/dt=" + exact(dt)};
}

}  // namespace mssph::validation
