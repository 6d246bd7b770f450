#include "fluid_forces.hpp"

#include "model/smoothing_kernels.hpp"

namespace mssph::reference {

void compute_pressure_viscosity_forces(const ParticleSetup& setup, const NeighbourLists& neighbours,
                                       ParticleState& state) {
  const SpikyGradient grad_w(setup.smoothing_length);
  const ViscosityLaplacian lap_w(setup.smoothing_length);
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
        const double v_i = state.volume[i];
        const double v_j = state.volume[j];
        const Eigen::Vector3d pressure = pressure_force_pair(v_i, state.pressure[i], v_j, state.pressure[j],
                                                             setup.gradient_consistency, grad_w(r_ij));
        const double mu = same_body ? body_i.material.viscosity
                                    : interface_viscosity(body_i.material.viscosity, body_j.material.viscosity);
        const Eigen::Vector3d viscosity =
            viscosity_force_pair(mu, v_i, v_j, lap_w(r_ij.norm()), state.velocity[i], state.velocity[j]);
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
