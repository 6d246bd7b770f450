#include "read_back.hpp"

#include "eigen_conversion.hpp"

#include <stdexcept>
#include <string>

namespace mssph::kernels {

std::uint32_t movable_rigid_index(const FloatScene& scene, std::size_t body) {
  const std::uint32_t index = body < scene.bodies.size() ? scene.bodies[body].rigid_index : kNotRigid;
  if (index == kNotRigid) throw std::invalid_argument("body " + std::to_string(body) + " is not a movable rigid body");
  return index;
}

ForceEvaluation pack_force_evaluation(const FloatScene& scene, const std::vector<std::uint32_t>& sorted_id,
                                      const std::vector<VolumePressure>& volume_pressure,
                                      const std::vector<ForceSum>& force_sum, const std::vector<Vec4>& elastic_force,
                                      const std::vector<Quat>& rotation) {
  const std::size_t n = sorted_id.size();
  ForceEvaluation out;
  out.density.resize(n);
  out.pressure.resize(n);
  out.pressure_force.resize(n);
  out.viscosity_force.resize(n);
  out.elastic_force.assign(n, Eigen::Vector3d::Zero());
  out.rotation.assign(n, Eigen::Matrix3d::Identity());
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t i = sorted_id[s];
    out.density[i] = particle_density(scene, i, volume_pressure[s]);
    out.pressure[i] = volume_pressure[s].pressure;
    out.pressure_force[i] = to_eigen(force_sum[s].pressure);
    out.viscosity_force[i] = to_eigen(force_sum[s].viscosity);
    if (!elastic_force.empty()) out.elastic_force[i] = to_eigen(xyz(elastic_force[i]));
  }
  for (std::uint32_t d = 0; d < rotation.size(); ++d) {
    const ElasticParameters& body = scene.elastic_bodies[scene.deformable_body[d]];
    const Mat3 r = rotation_matrix(rotation[d]);
    Eigen::Matrix3d& out_r = out.rotation[particle_index(body, d)];
    for (int k = 0; k < 9; ++k) out_r(k / 3, k % 3) = r.m[k];
  }
  return out;
}

}  // namespace mssph::kernels
