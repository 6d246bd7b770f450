#pragma once
// Small scenes for physics tests, built through the same JSON path as user scenes.
#include "config/scene_loader.hpp"
#include "model/scene_builder.hpp"
#include "reference_backend.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace mssph::testing {

inline nlohmann::json vec(double x, double y, double z) { return nlohmann::json::array({x, y, z}); }

// A scene document with the given simulation settings and no bodies yet.
inline nlohmann::json scene_document(double dx, double dt, double duration,
                                     const nlohmann::json& gravity = vec(0, 0, -9.81)) {
  return {{"name", "test"},
          {"simulation",
           {{"dt", dt}, {"duration", duration}, {"particle_spacing", dx}, {"gravity", gravity}, {"max_speed", 50.0}}},
          {"bodies", nlohmann::json::object()}};
}

inline reference::ReferenceBackend make_reference(const nlohmann::json& document) {
  return reference::ReferenceBackend(build_particles(parse_scene(document, "test scene")));
}

inline std::size_t body_index(const ParticleSetup& setup, const std::string& name) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == name) return b;
  }
  throw std::invalid_argument("no body " + name);
}

inline void run_steps(Backend& backend, std::size_t steps) {
  for (std::size_t s = 0; s < steps; ++s) backend.step();
}

}  // namespace mssph::testing
