#pragma once
// What the logs and the haptic loop read back from the GPU: every body's sums for a logged
// sample (one kernel, one copy), and one rigid body's state for a haptic tick, from the copy a
// logged sample left when no step has run since.
#include "device_state.cuh"
#include "pinned_buffer.hpp"

#include <cstdint>
#include <vector>

namespace mssph::kernels {

class BodyReadback {
 public:
  // The scene and bodies are the backend's and outlive this.
  BodyReadback(const FloatScene& scene, const std::vector<BodySetup>& bodies, const ChunkTables& chunks);

  // Every body's logged state after `steps` steps.
  std::vector<BodyState> body_states(DeviceState& state, std::uint64_t steps, cudaStream_t stream);
  // The state of movable rigid body `rigid` (BodyParameters::rigid_index) of `body` after `steps`.
  BodyState rigid_body_state(const DeviceState& state, std::size_t body, std::uint32_t rigid, std::uint64_t steps,
                             cudaStream_t stream);

 private:
  const FloatScene& scene_;
  const std::vector<BodySetup>& bodies_;
  std::vector<BodyChunk> chunks_;   // the body chunks, in the order of their partial sums
  ReadbackLayout layout_;
  std::vector<float> rigid_reach_;  // per movable rigid body: max |r0| over its particles [m]
  std::vector<RigidBody> rigid_host_;     // the rigid bodies as last read back...
  std::uint64_t rigid_host_step_ = ~0ull;  // ...after this many steps
  PinnedBuffer<unsigned char> readback_host_;  // where the read-back buffer lands
  PinnedBuffer<RigidBody> tick_host_;          // where a haptic tick's rigid body lands
};

}  // namespace mssph::kernels
