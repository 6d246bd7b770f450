#include "elastic_forces.hpp"

#include "corotation.hpp"
#include "elasticity.hpp"
#include "sph_kernels.hpp"

namespace mssph::reference {
namespace {

bool is_deformable(const ParticleSetup& setup, std::size_t i) {
  return setup.bodies[setup.body[i]].kind == BodyKind::deformable;
}

}  // namespace

void compute_rotations(const ParticleSetup& setup, const DeformableRestState& rest,
                       const std::vector<Eigen::Vector3d>& positions, DeformableState& state) {
  const Poly6Kernel w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i)) continue;
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    for (const std::size_t* jp = rest.neighbours.begin(i); jp != rest.neighbours.end(i); ++jp) {
      const std::size_t j = *jp;
      const Eigen::Vector3d rest_x_ij = rest.position[j] - rest.position[i];
      a += moment_matrix_term(setup.mass[j] * w(rest_x_ij.squaredNorm()), positions[j] - positions[i], rest_x_ij);
    }
    state.rotation[i] = rotation_from_moment_matrix(a, state.rotation[i]);
  }
}

void compute_elastic_stresses(const ParticleSetup& setup, const DeformableRestState& rest,
                              const std::vector<Eigen::Vector3d>& positions, DeformableState& state) {
  const SpikyGradient grad_w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i)) continue;
    const Material& material = setup.bodies[setup.body[i]].material;
    Eigen::Matrix3d grad_u = Eigen::Matrix3d::Zero();
    for (const std::size_t* jp = rest.neighbours.begin(i); jp != rest.neighbours.end(i); ++jp) {
      const std::size_t j = *jp;
      const Eigen::Vector3d rest_x_ij = rest.position[j] - rest.position[i];
      const Eigen::Vector3d d_ij = rest_gradient(rest.volume[j], rest.correction[i], grad_w(-rest_x_ij));
      const Eigen::Vector3d u_ji = rotated_displacement(state.rotation[i], positions[j] - positions[i], rest_x_ij);
      grad_u += displacement_gradient_term(u_ji, d_ij);
    }
    const Eigen::Matrix3d eps = strain(grad_u, material.strain);
    const Eigen::Matrix3d sigma = isotropic_stress(eps, rest.lame[i]);
    state.displacement_gradient[i] = grad_u;
    state.strain[i] = eps;
    state.stress[i] = sigma;
    state.stress_action[i] =
        stress_action(rest.volume[i], state.rotation[i], first_piola_kirchhoff(grad_u, sigma, material.strain));
    state.strain_energy[i] = rest.volume[i] * strain_energy_density(eps, rest.lame[i]);
  }
}

void compute_elastic_forces(const ParticleSetup& setup, const DeformableRestState& rest, DeformableState& state) {
  const SpikyGradient grad_w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (const std::size_t* jp = rest.neighbours.begin(i); jp != rest.neighbours.end(i); ++jp) {
      const std::size_t j = *jp;
      const Eigen::Vector3d rest_x_ij = rest.position[j] - rest.position[i];
      const Eigen::Vector3d d_ij = rest_gradient(rest.volume[j], rest.correction[i], grad_w(-rest_x_ij));
      const Eigen::Vector3d d_ji = rest_gradient(rest.volume[i], rest.correction[j], grad_w(rest_x_ij));
      force += elastic_force_term(state.stress_action[i], d_ij, state.stress_action[j], d_ji);
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
