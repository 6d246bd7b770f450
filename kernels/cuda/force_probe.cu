#include "force_probe.cuh"

#include "../common/fluid_physics.hpp"
#include "thread_blocks.cuh"

namespace mssph::kernels {
namespace {

// The same sum as forces_kernel's, one lane per particle, not integrated.
__global__ void force_probe_kernel(SortedView view, ForceSum* forces) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < view.step.particle_count) forces[s] = force_sum(view, load_force_particle(view, s), 0, 1);
}

}  // namespace

ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  // Outside the scene's device arrays: a probe runs in tests and validation, never in a step.
  DeviceBuffer<ForceSum> forces(n);
  force_probe_kernel<<<blocks_for(n), kBlock, 0, stream>>>(sorted_view(scene, state), forces.data());
  cuda_check(cudaGetLastError(), "launch force probe");
  cuda_check(cudaStreamSynchronize(stream), "evaluate forces");
  const std::vector<ForceSum> sums = forces.download();
  const std::vector<VolumePressure> vp = state.volume_pressure.download();
  const std::vector<std::uint32_t> id = state.sorted_id.download();
  const bool deformable = state.elastic_force.size() > 0;
  const std::vector<Vec4> elastic = deformable ? state.elastic_force.download() : std::vector<Vec4>(n, Vec4{0, 0, 0, 0});
  const std::vector<Quat> rotation = deformable ? state.rotation.download() : std::vector<Quat>{};
  const auto to_eigen = [](Vec3 v) { return Eigen::Vector3d(v.x, v.y, v.z); };
  ForceEvaluation out;
  out.density.resize(n);
  out.pressure.resize(n);
  out.pressure_force.resize(n);
  out.viscosity_force.resize(n);
  out.elastic_force.resize(n);
  out.rotation.assign(n, Eigen::Matrix3d::Identity());
  for (std::uint32_t s = 0; s < n; ++s) {
    const std::uint32_t i = id[s];
    out.density[i] = scene.bodies[scene.body[i]].sph_mass / vp[s].volume;
    out.pressure[i] = vp[s].pressure;
    out.pressure_force[i] = to_eigen(sums[s].pressure);
    out.viscosity_force[i] = to_eigen(sums[s].viscosity);
    out.elastic_force[i] = to_eigen(xyz(elastic[i]));
  }
  for (std::uint32_t d = 0; d < rotation.size(); ++d) {
    const ElasticParameters& body = scene.elastic_bodies[scene.deformable_body[d]];
    const Mat3 r = rotation_matrix(rotation[d]);
    Eigen::Matrix3d& out_r = out.rotation[body.first_particle + (d - body.first_deformable)];
    for (int k = 0; k < 9; ++k) out_r(k / 3, k % 3) = r.m[k];
  }
  return out;
}

}  // namespace mssph::kernels
