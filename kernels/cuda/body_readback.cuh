#pragma once
// What the logs and the haptic loop read back from the GPU, from mapped host memory that the
// kernels store into (mapped_host_buffer.hpp): every body's sums for a logged sample (one kernel
// and a wait), and the movable rigid bodies, which every step leaves there (a wait only).
#include "device_state.cuh"
#include "mapped_host_buffer.hpp"

#include <cstdint>
#include <vector>

namespace mssph::kernels {

class BodyReadback {
 public:
  // The scene and bodies are the backend's and outlive this.
  BodyReadback(const FloatScene& scene, const std::vector<BodySetup>& bodies, const ChunkTables& chunks);

  // Where the step's rigid-body kernel stores each movable rigid body once integrated.
  RigidBody* rigid_bodies_on_device() { return rigid_bodies_.device_data(); }
  // After the host replaced the device's rigid bodies (a restored checkpoint), with no step in
  // flight: the same records here.
  void set_rigid_bodies(const std::vector<RigidBody>& bodies);

  // Every body's logged state after the steps launched so far.
  std::vector<BodyState> body_states(DeviceState& state, cudaStream_t stream);
  // The state of movable rigid body `rigid` (BodyParameters::rigid_index) of `body`, likewise.
  BodyState rigid_body_state(std::size_t body, std::uint32_t rigid, cudaStream_t stream);

 private:
  const FloatScene& scene_;
  const std::vector<BodySetup>& bodies_;
  std::vector<BodyChunk> chunks_;             // the body chunks, in the order of their partial sums
  std::vector<float> rigid_reach_;            // per movable rigid body: max |r0| over its particles [m]
  MappedHostBuffer<BodySums> partial_sums_;   // per body chunk, stored by the body-sums kernel
  MappedHostBuffer<RigidBody> rigid_bodies_;  // as the last step left them
};

}  // namespace mssph::kernels
