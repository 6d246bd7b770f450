#include "force_probe.cuh"

#include "../common/fluid_physics.hpp"
#include "../common/read_back.hpp"
#include "thread_blocks.cuh"

namespace mssph::kernels {
namespace {

// The same sum as forces_kernel's, one lane per particle, not integrated: skipped, as there, where
// the density pass found no other body within h of a rigid or deformable particle.
template <bool FullStress>
__global__ void force_probe_kernel(SortedView view, const std::uint8_t* near_other_body, NearNotes notes,
                                   ForceSum* forces) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= view.step.particle_count) return;
  const ForceParticle p = load_force_particle(view, s);
  HeldSegments<kHeldSegments> held;
  forces[s] = may_feel_forces(p.parameters, near_other_body[s] != 0)
                  ? force_sum<FullStress>(view, p, view.id[s], notes, held)
                  : zero_force_sum();
}

}  // namespace

ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, const NearNotes& notes, cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  // Outside the scene's device arrays: a probe runs in tests and validation, never in a step.
  DeviceBuffer<ForceSum> forces(n);
  const SortedView view = sorted_view(scene, state);
  if (scene.full_stress_viscosity) {
    force_probe_kernel<true>
        <<<blocks_for(n), kBlock, 0, stream>>>(view, state.near_other_body.data(), notes, forces.data());
  } else {
    force_probe_kernel<false>
        <<<blocks_for(n), kBlock, 0, stream>>>(view, state.near_other_body.data(), notes, forces.data());
  }
  cuda_check(cudaGetLastError(), "launch force probe");
  cuda_check(cudaStreamSynchronize(stream), "evaluate forces");
  const bool deformable = state.elastic_force.size() > 0;
  return pack_force_evaluation(scene, state.sorted_id.download(), state.volume_pressure.download(), forces.download(),
                               deformable ? state.elastic_force.download() : std::vector<Vec4>{},
                               deformable ? state.rotation.download() : std::vector<Quat>{});
}

}  // namespace mssph::kernels
