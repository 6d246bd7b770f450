#include "fluid_forces.hpp"

#include "model/smoothing_kernels.hpp"

#include <Eigen/LU>

namespace mssph::reference {

namespace {

// The mu of eq. 3 between particles i and j of bodies body_i and body_j.
double pair_viscosity(const BodySetup& body_i, const BodySetup& body_j, bool same_body) {
  return same_body ? body_i.material.viscosity
                   : interface_viscosity(body_i.material.viscosity, body_j.material.viscosity);
}

}  // namespace

Eigen::Matrix3d VelocityGradientSums::gradient() const {
  Eigen::Matrix3d inverse;
  bool invertible = false;
  position_moment.computeInverseWithCheck(inverse, invertible);
  return invertible ? Eigen::Matrix3d(velocity_moment * inverse) : Eigen::Matrix3d::Zero();
}

void compute_velocity_gradients(const ParticleSetup& setup, const NeighbourLists& neighbours, ParticleState& state) {
  const SpikyGradient grad_w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const BodySetup& body_i = setup.bodies[setup.body[i]];
    state.velocity_gradient[i].setZero();
    if (body_i.kind != BodyKind::fluid) continue;
    VelocityGradientSums sums;
    for (const std::size_t* jp = neighbours.begin(i); jp != neighbours.end(i); ++jp) {
      const std::size_t j = *jp;
      if (j == i) continue;
      const BodySetup& body_j = setup.bodies[setup.body[j]];
      if (pair_viscosity(body_i, body_j, setup.body[j] == setup.body[i]) <= 0.0) continue;
      sums.add(state.volume[j], state.velocity[j] - state.velocity[i], state.position[j] - state.position[i],
               grad_w(state.position[i] - state.position[j]));
    }
    state.velocity_gradient[i] = sums.gradient();
  }
}

void compute_pressure_viscosity_forces(const ParticleSetup& setup, const NeighbourLists& neighbours,
                                       ParticleState& state) {
  const SpikyGradient grad_w(setup.smoothing_length);
  const ViscosityLaplacian lap_w(setup.smoothing_length);
  const bool full_stress = setup.viscosity_model == ViscosityModel::full_stress;
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d internal = Eigen::Vector3d::Zero();
    Eigen::Vector3d interaction = Eigen::Vector3d::Zero();
    Eigen::Vector3d pressure_sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d viscosity_sum = Eigen::Vector3d::Zero();
    const BodySetup& body_i = setup.bodies[setup.body[i]];
    if (body_i.kind != BodyKind::boundary) {
      for (const std::size_t* jp = neighbours.begin(i); jp != neighbours.end(i); ++jp) {
        const std::size_t j = *jp;
        if (j == i) continue;
        const bool same_body = setup.body[j] == setup.body[i];
        if (same_body && body_i.kind != BodyKind::fluid) continue;
        const BodySetup& body_j = setup.bodies[setup.body[j]];
        const Eigen::Vector3d r_ij = state.position[i] - state.position[j];
        const Eigen::Vector3d grad_w_ij = grad_w(r_ij);
        const double v_i = state.volume[i];
        const double v_j = state.volume[j];
        const Eigen::Vector3d pressure =
            pressure_force_pair(v_i, state.pressure[i], v_j, state.pressure[j], setup.gradient_consistency, grad_w_ij);
        const double mu = pair_viscosity(body_i, body_j, same_body);
        Eigen::Vector3d viscosity =
            viscosity_force_pair(mu, v_i, v_j, lap_w(r_ij.norm()), state.velocity[i], state.velocity[j]);
        const bool fluid_i = body_i.kind == BodyKind::fluid;
        const bool fluid_j = body_j.kind == BodyKind::fluid;
        if (full_stress && mu > 0.0 && (fluid_i || fluid_j)) {
          const Eigen::Matrix3d& a_i = state.velocity_gradient[fluid_i ? i : j];
          const Eigen::Matrix3d& a_j = state.velocity_gradient[fluid_j ? j : i];
          viscosity += transposed_stress_force_pair(mu, v_i, a_i, v_j, a_j, setup.gradient_consistency, grad_w_ij);
        }
        if (same_body) {
          internal += pressure + viscosity;
        } else {
          interaction += interaction_force(pressure, viscosity);
        }
        pressure_sum += pressure;
        viscosity_sum += viscosity;
      }
    }
    state.internal_force[i] = internal;
    state.interaction_force[i] = interaction;
    state.pressure_force[i] = pressure_sum;
    state.viscosity_force[i] = viscosity_sum;
  }
}

}  // namespace mssph::reference
