#include "elastic_statics.hpp"

#include "elastic_bodies.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>

namespace mssph::validation {

reference::ReferenceBackend patch_block(bool correction, const std::string& strain, double jitter) {
  const Scene scene = case_scene(
      "physics/patch_tests", {"simulation/jitter=" + exact(jitter),
                              std::string("bodies/block/kernel_gradient_correction=") + (correction ? "true" : "false"),
                              "bodies/block/strain=" + strain});
  return reference::ReferenceBackend(build_particles(scene));
}

std::vector<Eigen::Matrix3d> interior_stresses(reference::ReferenceBackend& backend, const Eigen::Matrix3d& g) {
  deform_body(backend, 0, g, Eigen::Vector3d::Zero());
  backend.compute_forces();
  std::vector<Eigen::Matrix3d> stresses;
  for (std::size_t i : interior_particles(backend, 0, backend.setup().smoothing_length)) {
    stresses.push_back(backend.deformables().stress[i]);
  }
  return stresses;
}

double farthest_from(const std::vector<Eigen::Matrix3d>& stresses, double target, double (*f)(const Eigen::Matrix3d&)) {
  double farthest = target;
  for (const Eigen::Matrix3d& s : stresses) {
    if (!(std::abs(f(s) - target) <= std::abs(farthest - target))) farthest = f(s);
  }
  return farthest;
}

RigidMotionResiduals rigid_motion_residuals(bool jitter, bool correction) {
  const Scene scene =
      case_scene("physics/rotation_invariance",
                 {"simulation/jitter=" + std::string(jitter ? "0.2" : "0"),
                  std::string("bodies/block/kernel_gradient_correction=") + (correction ? "true" : "false")});
  reference::ReferenceBackend backend(build_particles(scene));
  const BodyConfig& block = scene.bodies.front();
  const double h = backend.setup().smoothing_length;
  const double force_scale = block.material.young_modulus * h * h;
  // Rotations about random axes by angles spread over (0, pi], pi itself included.
  std::mt19937_64 random(2011);
  std::normal_distribution<double> normal(0.0, 1.0);
  RigidMotionResiduals r;
  const int count = 12;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d axis = Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
    const double angle = std::numbers::pi * static_cast<double>(k + 1) / static_cast<double>(count);
    const Eigen::Matrix3d q = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    deform_body(backend, 0, q, block.position, Eigen::Vector3d(1.5, -2.0, 0.7));
    backend.compute_forces();
    for (std::size_t i = 0; i < backend.particle_count(); ++i) {
      r.worst_rotation = std::max(r.worst_rotation, (backend.deformables().rotation[i] - q).cwiseAbs().maxCoeff());
      r.worst_force = std::max(r.worst_force, backend.deformables().elastic_force[i].norm() / force_scale);
    }
  }
  return r;
}

}  // namespace mssph::validation
