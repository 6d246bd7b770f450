#include "body_readback.cuh"

#include "chunk_particles.cuh"

#include <cub/cub.cuh>

#include <cstring>

namespace mssph::kernels {
namespace {

struct BodySumsCombine {
  __device__ BodySums operator()(const BodySums& a, const BodySums& b) const { return combine(a, b); }
};

// One block per chunk: partial sums behind the logged body states; the host adds a body's chunks
// in order.
__global__ void body_sums_kernel(const BodyChunk* chunks, const BodyParameters* bodies, CanonicalState state,
                                 const Mat3* deformation, BodySums* partial) {
  using BlockReduce = cub::BlockReduce<BodySums, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  const BodyChunk chunk = chunks[blockIdx.x];
  const float mass = bodies[chunk.body].sph_mass;
  BodySums acc = zero_body_sums();
  for_each_chunk_particle(chunk.first, chunk.count, [&](std::uint32_t i) {
    add_particle(acc, xyz(state.position[i]), xyz(state.velocity[i]), mass, xyz(state.interaction_force[i]));
    add_domain_status(acc, state.fixed[i]);
    if (chunk.first_deformable != kNotDeformable) {
      add_volume_ratio(acc, determinant(deformation[chunk.first_deformable + (i - chunk.first)]),
                       chunk.lowest_valid_volume_ratio);
    }
  });
  const BodySums total = BlockReduce(reduce_storage).Reduce(acc, BodySumsCombine());
  if (threadIdx.x == 0) partial[blockIdx.x] = total;
}

}  // namespace

BodyReadback::BodyReadback(const FloatScene& scene, const std::vector<BodySetup>& bodies, const ChunkTables& chunks)
    : scene_(scene),
      bodies_(bodies),
      chunks_(chunks.body),
      layout_(chunks.body.size(), scene.rigid_bodies.size()),
      readback_host_(layout_.bytes),
      tick_host_(1) {
  for (const RigidBody& r : scene.rigid_bodies) {
    float reach = 0.0f;
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) reach = std::max(reach, norm(xyz(scene.rest_offset[i])));
    rigid_reach_.push_back(reach);
  }
}

// The chunk sums and a device-side copy of the rigid bodies land side by side in the read-back
// buffer, which comes back in one copy.
std::vector<BodyState> BodyReadback::body_states(DeviceState& state, std::uint64_t steps, cudaStream_t stream) {
  auto* partial_sums = reinterpret_cast<BodySums*>(state.readback.data());
  body_sums_kernel<<<static_cast<unsigned>(chunks_.size()), kBlock, 0, stream>>>(
      state.body_chunks.data(), state.bodies.data(), canonical_state(state), state.deformation.data(), partial_sums);
  cuda_check(cudaGetLastError(), "launch body sums");
  if (!scene_.rigid_bodies.empty()) {
    cuda_check(cudaMemcpyAsync(state.readback.data() + layout_.rigid_offset, state.rigid_bodies.data(),
                               state.rigid_bodies.bytes(), cudaMemcpyDeviceToDevice, stream),
               "gather rigid bodies");
  }
  const unsigned char* bytes = readback_host_.data();
  cuda_check(cudaMemcpyAsync(readback_host_.data(), state.readback.data(), readback_host_.bytes(), cudaMemcpyDeviceToHost,
                             stream),
             "download body states");
  cuda_check(cudaStreamSynchronize(stream), "body states");
  std::vector<BodySums> partial(chunks_.size());
  std::memcpy(partial.data(), bytes, partial.size() * sizeof(BodySums));
  rigid_host_.resize(scene_.rigid_bodies.size());
  std::memcpy(rigid_host_.data(), bytes + layout_.rigid_offset, rigid_host_.size() * sizeof(RigidBody));
  rigid_host_step_ = steps;
  std::vector<BodySums> sums(bodies_.size(), zero_body_sums());
  for (std::size_t c = 0; c < partial.size(); ++c) sums[chunks_[c].body] = combine(sums[chunks_[c].body], partial[c]);
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const std::uint32_t r = scene_.bodies[b].rigid_index;
    states.push_back(to_body_state(scene_, sums[b], r == kNotRigid ? nullptr : &rigid_host_[r], bodies_[b]));
  }
  return states;
}

// What a haptic tick needs: one small device-to-host copy, or none when a logged sample has read
// every body back since the last step. The fastest particle's speed is bounded by
// |v| + |omega| r_max instead of being summed over the particles.
BodyState BodyReadback::rigid_body_state(const DeviceState& state, std::size_t body, std::uint32_t rigid,
                                         std::uint64_t steps, cudaStream_t stream) {
  RigidBody copy{};
  if (rigid_host_step_ == steps) {
    copy = rigid_host_[rigid];
  } else {
    cuda_check(cudaMemcpyAsync(tick_host_.data(), state.rigid_bodies.data() + rigid, sizeof copy,
                               cudaMemcpyDeviceToHost, stream),
               "download rigid body");
    cuda_check(cudaStreamSynchronize(stream), "download rigid body");
    copy = *tick_host_.data();
  }
  BodySums sums = zero_body_sums();
  const double bound = norm(copy.velocity) + norm(angular_velocity(copy)) * rigid_reach_[rigid];
  sums.max_speed = bound * bound;
  return to_body_state(scene_, sums, &copy, bodies_[body]);
}

}  // namespace mssph::kernels
