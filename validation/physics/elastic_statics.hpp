#pragma once
// The elastic model's static properties on the reference backend (the float32 kernels are held
// to the reference by the kernels suite): patch tests of the SPH displacement gradient, strain
// and stress (paper eq. 4 and Hooke's law), and invariance under rigid rotations (paper eq. 5-6
// with corotation). Shared by the physics cases and tests/deformable.
#include "reference_backend.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mssph::validation {

// The block of validation/physics/patch_tests/scene.json with the given gradient correction,
// strain measure ("green_saint_venant", "cauchy") and lattice jitter.
reference::ReferenceBackend patch_block(bool correction, const std::string& strain, double jitter = 0.0);

// Deforms the patch block uniformly by G about its centre, evaluates the forces, and returns
// the stress at the interior particles (complete neighbourhoods, at least h from every face).
std::vector<Eigen::Matrix3d> interior_stresses(reference::ReferenceBackend& backend, const Eigen::Matrix3d& g);

// Of the values f(sigma) over the stresses, the one farthest from `target`.
double farthest_from(const std::vector<Eigen::Matrix3d>& stresses, double target, double (*f)(const Eigen::Matrix3d&));

// The block of validation/physics/rotation_invariance/scene.json, rotated rigidly by 12 rotations
// about random axes (angles spread over (0, pi], pi included) and translated: the largest
// |R_i - Q| entry and the largest elastic force over E h^2 seen.
struct RigidMotionResiduals {
  double worst_rotation = 0.0;
  double worst_force = 0.0;  // |f_i| / (E h^2)
};
RigidMotionResiduals rigid_motion_residuals(bool jitter, bool correction);

}  // namespace mssph::validation
