#pragma once
// Deformable-body scenes for the elasticity tests, built through the same JSON path as user
// scenes, and helpers that read the reference backend's deformable state.
#include "config/scene_loader.hpp"
#include "reference_backend.hpp"
#include "scene/scene_builder.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <vector>

namespace mssph::testing {

inline nlohmann::json vec3(double x, double y, double z) { return nlohmann::json::array({x, y, z}); }

// A scene with no gravity unless given, h = 2 dx (the default), and no bodies yet.
inline nlohmann::json elastic_scene(double dx, double dt, const nlohmann::json& gravity = vec3(0, 0, 0)) {
  return {{"name", "elastic_test"},
          {"simulation", {{"dt", dt}, {"duration", 1.0}, {"particle_spacing", dx}, {"gravity", gravity}, {"max_speed", 100.0}}},
          {"bodies", nlohmann::json::object()}};
}

// Material keys of a deformable body: rho0 = 1000 kg/m^3 and a pressure stiffness that only
// matters for contact with other bodies.
inline nlohmann::json elastic_material(double young_modulus, double poisson_ratio) {
  return {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}, {"viscosity", 0.0},
          {"young_modulus", young_modulus}, {"poisson_ratio", poisson_ratio}};
}

// A deformable box body centred at `centre` with the given material keys (more keys may be added
// to the returned object, e.g. fixed_regions).
inline nlohmann::json deformable_box(const Eigen::Vector3d& size, const Eigen::Vector3d& centre, nlohmann::json material) {
  material["kind"] = "deformable";
  material["shape"] = {{"type", "box"}, {"size", vec3(size.x(), size.y(), size.z())}};
  material["position"] = vec3(centre.x(), centre.y(), centre.z());
  return material;
}

inline reference::ReferenceBackend make_backend(const nlohmann::json& document) {
  return reference::ReferenceBackend(build_particles(parse_scene(document, "elastic test scene")));
}

// Particles of `body` whose rest neighbourhood is complete: at least `margin` from every face of
// the body's bounding box (margin >= h: the support lies inside the body).
inline std::vector<std::size_t> interior_particles(const reference::ReferenceBackend& backend, std::size_t body,
                                                   double margin) {
  const BodySetup& b = backend.setup().bodies[body];
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    lo = lo.cwiseMin(backend.setup().position[i]);
    hi = hi.cwiseMax(backend.setup().position[i]);
  }
  std::vector<std::size_t> inside;
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    const Eigen::Vector3d& x = backend.setup().position[i];
    if (((x - lo).array() >= margin - 1e-12).all() && ((hi - x).array() >= margin - 1e-12).all()) inside.push_back(i);
  }
  return inside;
}

// Places every particle of `body` at x = centre + G (X - centre) + t from its rest position X:
// a uniform deformation G (a rotation, a stretch, a shear) and a translation t.
inline void deform_body(reference::ReferenceBackend& backend, std::size_t body, const Eigen::Matrix3d& g,
                        const Eigen::Vector3d& centre, const Eigen::Vector3d& translation = Eigen::Vector3d::Zero()) {
  const BodySetup& b = backend.setup().bodies[body];
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    backend.particles().position[i] = centre + g * (backend.setup().position[i] - centre) + translation;
  }
}

}  // namespace mssph::testing
