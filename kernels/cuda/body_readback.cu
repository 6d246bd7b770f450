#include "body_readback.cuh"

#include "chunk_particles.cuh"

#include <cub/cub.cuh>

#include <algorithm>

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
      partial_sums_(chunks.body.size()),
      rigid_bodies_(scene.rigid_bodies.size()) {
  for (const RigidBody& r : scene.rigid_bodies) {
    float reach = 0.0f;
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i)
      reach = std::max(reach, norm(xyz(scene.rest_offset[i])));
    rigid_reach_.push_back(reach);
  }
  set_rigid_bodies(scene.rigid_bodies);  // what the device starts from
}

void BodyReadback::set_rigid_bodies(const std::vector<RigidBody>& bodies) {
  std::copy(bodies.begin(), bodies.end(), rigid_bodies_.data());
}

std::vector<BodyState> BodyReadback::body_states(DeviceState& state, cudaStream_t stream) {
  body_sums_kernel<<<static_cast<unsigned>(chunks_.size()), kBlock, 0, stream>>>(
      state.body_chunks.data(), state.bodies.data(), canonical_state(state), state.deformation.data(),
      partial_sums_.device_data());
  cuda_check(cudaGetLastError(), "launch body sums");
  cuda_check(cudaStreamSynchronize(stream), "body states");
  std::vector<BodySums> sums(bodies_.size(), zero_body_sums());
  for (std::size_t c = 0; c < chunks_.size(); ++c) {
    sums[chunks_[c].body] = combine(sums[chunks_[c].body], partial_sums_.data()[c]);
  }
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const std::uint32_t r = scene_.bodies[b].rigid_index;
    states.push_back(to_body_state(scene_, sums[b], r == kNotRigid ? nullptr : rigid_bodies_.data() + r, bodies_[b]));
  }
  return states;
}

// What a haptic tick needs: a wait for the stream. The fastest particle's speed is bounded by
// |v| + |omega| r_max instead of being summed over the particles.
BodyState BodyReadback::rigid_body_state(std::size_t body, std::uint32_t rigid, cudaStream_t stream) {
  cuda_check(cudaStreamSynchronize(stream), "wait for the rigid bodies");
  const RigidBody& copy = rigid_bodies_.data()[rigid];
  BodySums sums = zero_body_sums();
  const double bound = norm(copy.velocity) + norm(angular_velocity(copy)) * rigid_reach_[rigid];
  sums.max_speed = bound * bound;
  return to_body_state(scene_, sums, &copy, bodies_[body]);
}

}  // namespace mssph::kernels
