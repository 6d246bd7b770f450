#pragma once
// What the float backends report through the Backend interface, computed once for both: the
// `cpu` backend passes its host arrays, the `cuda` backend the arrays it downloaded.
#include "float_scene.hpp"
#include "fluid_physics.hpp"

#include <cstdint>
#include <vector>

namespace mssph::kernels {

// rho_i = m_i / V_i from the density pass's volume V_i = m_i / rho_i; 0 before any density pass
// (V_i still 0).
inline float particle_density(const FloatScene& scene, std::uint32_t i, VolumePressure vp) {
  return vp.volume > 0.0f ? scene.bodies[scene.body[i]].sph_mass / vp.volume : 0.0f;
}

// The index into scene.rigid_bodies of body `body`; throws std::invalid_argument when it does not
// move as a rigid body (a fluid, deformable, boundary or fixed body, or no such body).
std::uint32_t movable_rigid_index(const FloatScene& scene, std::size_t body);

// Backend::evaluate_forces in canonical order from one force evaluation:
//   sorted_id[s]        canonical index of the particle in sorted slot s (n entries)
//   volume_pressure[s]  the density pass's output, sorted order (n entries)
//   force_sum[s]        force_sum() of the particle in sorted slot s (n entries)
//   elastic_force[i]    eq. 5-6 force, canonical order (n entries, or empty: no deformable body)
//   rotation[d]         R_i of deformable particle d (scene.deformable_body.size() entries, or empty)
ForceEvaluation pack_force_evaluation(const FloatScene& scene, const std::vector<std::uint32_t>& sorted_id,
                                      const std::vector<VolumePressure>& volume_pressure,
                                      const std::vector<ForceSum>& force_sum, const std::vector<Vec4>& elastic_force,
                                      const std::vector<Quat>& rotation);

}  // namespace mssph::kernels
