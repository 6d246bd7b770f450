#include "force_probe.cuh"

#include "../common/fluid_physics.hpp"
#include "../common/read_back.hpp"
#include "contact_order.cuh"
#include "thread_blocks.cuh"

namespace mssph::kernels {
namespace {

// The same sum as forces_kernel's, one lane per particle, not integrated: its teams serve the same
// particles (force_seat), and skip the walk where it does.
template <bool FullStress>
__global__ void force_probe_kernel(SortedView view, ForceWalks walks, NearNotes notes, ForceSum* forces) {
  const ForceSeat seat = force_seat(view, walks, blockIdx.x * blockDim.x + threadIdx.x);
  if (!seat.active) return;
  const ForceParticle p = load_force_particle(view, seat.s);
  HeldSegments<kHeldSegments> held;
  forces[seat.s] = seat.walks ? force_sum<FullStress>(view, p, view.id[seat.s], notes, held) : zero_force_sum();
}

}  // namespace

ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, const NearNotes& notes, cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  // Outside the scene's device arrays: a probe runs in tests and validation, never in a step.
  DeviceBuffer<ForceSum> forces(n);
  const SortedView view = sorted_view(scene, state);
  const ForceWalks walks = force_walks(state);
  const unsigned blocks = blocks_for(std::size_t{n} + walks.contact_capacity);
  if (scene.full_stress_viscosity) {
    force_probe_kernel<true><<<blocks, kBlock, 0, stream>>>(view, walks, notes, forces.data());
  } else {
    force_probe_kernel<false><<<blocks, kBlock, 0, stream>>>(view, walks, notes, forces.data());
  }
  cuda_check(cudaGetLastError(), "launch force probe");
  cuda_check(cudaStreamSynchronize(stream), "evaluate forces");
  const bool deformable = state.elastic_force.size() > 0;
  return pack_force_evaluation(scene, state.sorted_id.download(), state.volume_pressure.download(), forces.download(),
                               deformable ? state.elastic_force.download() : std::vector<Vec4>{},
                               deformable ? state.rotation.download() : std::vector<Quat>{});
}

}  // namespace mssph::kernels
