#include "zero_energy_control.hpp"

#include "elasticity.hpp"

namespace mssph::reference {

void compute_zero_energy_forces(const ParticleSetup& setup, const DeformableRestState& rest,
                                const std::vector<Eigen::Vector3d>& positions, DeformableState& state) {
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Material& material = setup.bodies[setup.body[i]].material;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (is_deformable(setup, i) && material.zero_energy_stiffness > 0.0) {
      const Eigen::Matrix3d world_f_i = world_deformation_gradient(state.rotation[i], state.displacement_gradient[i]);
      for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
        const std::size_t j = rest.neighbours.indices[k];
        const RestBond& bond = rest.bonds[k];
        const Eigen::Matrix3d world_f_j = world_deformation_gradient(state.rotation[j], state.displacement_gradient[j]);
        force += zero_energy_force_pair(world_f_i, world_f_j, bond.offset, positions[j] - positions[i],
                                        rest.volume[i] * rest.volume[j], bond.kernel, material.young_modulus,
                                        material.zero_energy_stiffness);
      }
    }
    state.hourglass_force[i] = force;
  }
}

}  // namespace mssph::reference
