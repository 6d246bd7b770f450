#include "elastic_forces.hpp"

#include "corotation.hpp"
#include "elasticity.hpp"

namespace mssph::reference {

Eigen::Matrix3d moment_matrix(const DeformableRestState& rest, const std::vector<Eigen::Vector3d>& positions,
                              std::size_t i) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
    const RestBond& bond = rest.bonds[k];
    a += moment_matrix_term(bond.moment_weight, positions[rest.neighbours.indices[k]] - positions[i], bond.offset);
  }
  return a;
}

Eigen::Matrix3d displacement_gradient(const Eigen::Matrix3d& rotation_i, const DeformableRestState& rest,
                                      const std::vector<Eigen::Vector3d>& positions, std::size_t i) {
  Eigen::Matrix3d grad_u = Eigen::Matrix3d::Zero();
  for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
    const RestBond& bond = rest.bonds[k];
    const Eigen::Vector3d x_ij = positions[rest.neighbours.indices[k]] - positions[i];
    grad_u += displacement_gradient_term(rotated_displacement(rotation_i, x_ij, bond.offset), bond.d_ij);
  }
  return grad_u;
}

Eigen::Matrix3d velocity_gradient(const Eigen::Matrix3d& rotation_i, const DeformableRestState& rest,
                                  const std::vector<Eigen::Vector3d>& velocities, std::size_t i) {
  Eigen::Matrix3d grad_v = Eigen::Matrix3d::Zero();
  for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
    const Eigen::Vector3d v_ij = velocities[rest.neighbours.indices[k]] - velocities[i];
    grad_v += (rotation_i.transpose() * v_ij) * rest.bonds[k].d_ij.transpose();
  }
  return grad_v;
}

void compute_rotations(const ParticleSetup& setup, const DeformableRestState& rest,
                       const std::vector<Eigen::Vector3d>& positions, DeformableState& state) {
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i)) continue;
    state.rotation[i] = rotation_from_moment_matrix(moment_matrix(rest, positions, i), state.rotation[i]);
  }
}

void compute_elastic_stresses(const ParticleSetup& setup, const DeformableRestState& rest,
                              const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<Eigen::Vector3d>& velocities, DeformableState& state) {
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i)) continue;
    const Material& material = setup.bodies[setup.body[i]].material;
    const Eigen::Matrix3d grad_u = displacement_gradient(state.rotation[i], rest, positions, i);
    const ElasticResponse response = elastic_response(grad_u, rest.lame[i], material.model);
    state.viscous_stress[i] = material.viscous_modulus > 0.0
                                  ? viscous_stress(velocity_gradient(state.rotation[i], rest, velocities, i),
                                                   rest.lame[i], material.viscous_modulus / material.young_modulus)
                                  : Eigen::Matrix3d::Zero();
    state.displacement_gradient[i] = grad_u;
    state.strain[i] = response.strain;
    state.stress[i] = response.stress;
    state.stress_action[i] = stress_action(rest.volume[i], state.rotation[i],
                                           response.first_piola + viscous_first_piola(grad_u, state.viscous_stress[i]));
    state.strain_energy[i] = rest.volume[i] * response.energy_density;
  }
}

void compute_elastic_forces(const ParticleSetup& setup, const DeformableRestState& rest, DeformableState& state) {
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
      const RestBond& bond = rest.bonds[k];
      force += elastic_force_pair(state.stress_action[i], bond.d_ij, state.stress_action[rest.neighbours.indices[k]],
                                  bond.d_ji);
    }
    state.elastic_force[i] = force;
  }
}

double body_strain_energy(const ParticleSetup& setup, const DeformableState& state, std::size_t body) {
  const BodySetup& b = setup.bodies[body];
  double energy = 0.0;
  for (std::size_t i = b.first; i < b.first + b.count; ++i) energy += state.strain_energy[i];
  return energy;
}

}  // namespace mssph::reference
