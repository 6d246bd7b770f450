#pragma once
// The per-step state of deformable particles (paper 3.1.2), indexed by particle over the whole
// scene; entries of other particles stay at identity or zero.
#include <Eigen/Core>

#include <vector>

namespace mssph::reference {

struct DeformableState {
  // Step 1: R_i, the rotation of i's neighbourhood from its rest configuration.
  std::vector<Eigen::Matrix3d> rotation;
  // Step 2, in i's rotated rest frame: grad u_i (eq. 4), the material model's strain and stress
  // (ElasticResponse in elasticity.hpp) [-], [Pa].
  std::vector<Eigen::Matrix3d> displacement_gradient;
  std::vector<Eigen::Matrix3d> strain;
  std::vector<Eigen::Matrix3d> stress;
  std::vector<Eigen::Matrix3d> viscous_stress;  // Kelvin-Voigt sigma_v (zero where the body has none) [Pa]
  std::vector<Eigen::Matrix3d> stress_action;   // K_i = V0_i R_i (P_i + sigma_v,i), world frame [N m]
  std::vector<double> strain_energy;            // V0_i psi_i [J]
  // Step 3: forces from the particle's own body [N]; their sum goes to internal_force.
  std::vector<Eigen::Vector3d> elastic_force;    // eq. 5, 6
  std::vector<Eigen::Vector3d> hourglass_force;  // zero-energy-mode control (0 when off)
  std::vector<Eigen::Vector3d> damping_force;    // mass-proportional damping (0 when off)

  void resize(std::size_t n) {
    rotation.assign(n, Eigen::Matrix3d::Identity());
    displacement_gradient.assign(n, Eigen::Matrix3d::Zero());
    strain.assign(n, Eigen::Matrix3d::Zero());
    stress.assign(n, Eigen::Matrix3d::Zero());
    viscous_stress.assign(n, Eigen::Matrix3d::Zero());
    stress_action.assign(n, Eigen::Matrix3d::Zero());
    strain_energy.assign(n, 0.0);
    elastic_force.assign(n, Eigen::Vector3d::Zero());
    hourglass_force.assign(n, Eigen::Vector3d::Zero());
    damping_force.assign(n, Eigen::Vector3d::Zero());
  }
};

}  // namespace mssph::reference
