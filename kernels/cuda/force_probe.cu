#include "force_probe.cuh"

#include "../common/fluid_physics.hpp"
#include "../common/read_back.hpp"
#include "thread_blocks.cuh"

namespace mssph::kernels {
namespace {

// The same sum as forces_kernel's, one lane per particle, not integrated.
__global__ void force_probe_kernel(SortedView view, ForceSum* forces) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < view.step.particle_count) forces[s] = force_sum(view, load_force_particle(view, s));
}

}  // namespace

ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  // Outside the scene's device arrays: a probe runs in tests and validation, never in a step.
  DeviceBuffer<ForceSum> forces(n);
  force_probe_kernel<<<blocks_for(n), kBlock, 0, stream>>>(sorted_view(scene, state), forces.data());
  cuda_check(cudaGetLastError(), "launch force probe");
  cuda_check(cudaStreamSynchronize(stream), "evaluate forces");
  const bool deformable = state.elastic_force.size() > 0;
  return pack_force_evaluation(scene, state.sorted_id.download(), state.volume_pressure.download(), forces.download(),
                               deformable ? state.elastic_force.download() : std::vector<Vec4>{},
                               deformable ? state.rotation.download() : std::vector<Quat>{});
}

}  // namespace mssph::kernels
