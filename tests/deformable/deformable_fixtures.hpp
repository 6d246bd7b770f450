#pragma once
// Deformable-body scenes for the elasticity tests, built through the same JSON path as user
// scenes, and helpers that read the reference backend's deformable state.
#include "config/scene_loader.hpp"
#include "model/scene_builder.hpp"
#include "physics/elastic_bodies.hpp"
#include "reference_backend.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <vector>

namespace mssph::testing {

inline nlohmann::json vec3(double x, double y, double z) { return nlohmann::json::array({x, y, z}); }

// A scene with no gravity unless given, h = 2 dx (the default), and no bodies yet.
inline nlohmann::json elastic_scene(double dx, double dt, const nlohmann::json& gravity = vec3(0, 0, 0)) {
  return {{"name", "elastic_test"},
          {"simulation",
           {{"dt", dt}, {"duration", 1.0}, {"particle_spacing", dx}, {"gravity", gravity}, {"max_speed", 100.0}}},
          {"bodies", nlohmann::json::object()}};
}

// Material keys of a deformable body: rho0 = 1000 kg/m^3 and a pressure stiffness that only
// matters for contact with other bodies.
inline nlohmann::json elastic_material(double young_modulus, double poisson_ratio) {
  return {{"rest_density", 1000.0},
          {"pressure_stiffness", 100.0},
          {"viscosity", 0.0},
          {"young_modulus", young_modulus},
          {"poisson_ratio", poisson_ratio}};
}

// A deformable box body centred at `centre` with the given material keys (more keys may be added
// to the returned object, e.g. fixed_regions).
inline nlohmann::json deformable_box(const Eigen::Vector3d& size, const Eigen::Vector3d& centre,
                                     nlohmann::json material) {
  material["kind"] = "deformable";
  material["shape"] = {{"type", "box"}, {"size", vec3(size.x(), size.y(), size.z())}};
  material["position"] = vec3(centre.x(), centre.y(), centre.z());
  return material;
}

inline reference::ReferenceBackend make_backend(const nlohmann::json& document) {
  return reference::ReferenceBackend(build_particles(parse_scene(document, "elastic test scene")));
}

// Interior particles and uniform deformations: the validation cases' helpers
// (validation/physics/elastic_bodies.hpp).
inline std::vector<std::size_t> interior_particles(const reference::ReferenceBackend& backend, std::size_t body,
                                                   double margin) {
  return validation::interior_particles(backend, body, margin);
}

inline void deform_body(reference::ReferenceBackend& backend, std::size_t body, const Eigen::Matrix3d& g,
                        const Eigen::Vector3d& centre, const Eigen::Vector3d& translation = Eigen::Vector3d::Zero()) {
  validation::deform_body(backend, body, g, centre, translation);
}

}  // namespace mssph::testing
