#include "zero_energy_control.hpp"

#include "sph_kernels.hpp"

namespace mssph::reference {

void compute_zero_energy_forces(const ParticleSetup& setup, const DeformableRestState& rest,
                                const std::vector<Eigen::Vector3d>& positions, DeformableState& state) {
  const Poly6Kernel w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Material& material = setup.bodies[setup.body[i]].material;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (setup.bodies[setup.body[i]].kind == BodyKind::deformable && material.zero_energy_stiffness > 0.0) {
      const Eigen::Matrix3d world_f_i =
          state.rotation[i] * (Eigen::Matrix3d::Identity() + state.displacement_gradient[i]);
      for (const std::size_t* jp = rest.neighbours.begin(i); jp != rest.neighbours.end(i); ++jp) {
        const std::size_t j = *jp;
        const Eigen::Matrix3d world_f_j =
            state.rotation[j] * (Eigen::Matrix3d::Identity() + state.displacement_gradient[j]);
        const Eigen::Vector3d rest_x_ij = rest.position[j] - rest.position[i];
        force += zero_energy_force_term(world_f_i, world_f_j, rest_x_ij, positions[j] - positions[i],
                                        rest.volume[i] * rest.volume[j], w(rest_x_ij.squaredNorm()),
                                        material.young_modulus, material.zero_energy_stiffness);
      }
    }
    state.hourglass_force[i] = force;
  }
}

}  // namespace mssph::reference
