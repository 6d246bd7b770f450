#include "rigid_bodies.cuh"

#include "chunk_particles.cuh"

#include <cub/cub.cuh>

namespace mssph::kernels {
namespace {

struct WrenchSum {
  __device__ Wrench operator()(const Wrench& a, const Wrench& b) const { return a + b; }
};

// One block per chunk: the wrench of its particles' interaction forces about the body's centre.
// The block that finishes a body's last chunk (a ticket counter tells) then adds the body's chunk
// wrenches in chunk order and integrates the body (eq. 8, 9): which block does it varies, the sum's
// order does not, so runs repeat bit for bit. The body goes to `host_copy` too.
__global__ void rigid_wrench_integrate_kernel(const RigidChunk* chunks, RigidBody* bodies, RigidBody* host_copy,
                                              CanonicalState state, Wrench* partial,
                                              const std::uint32_t* first_chunk, std::uint32_t* tickets,
                                              StepParameters step) {
  using BlockReduce = cub::BlockReduce<Wrench, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  __shared__ Wrench tile[kBlock];
  __shared__ bool last;
  const RigidChunk chunk = chunks[blockIdx.x];
  const Vec3 centre = bodies[chunk.rigid].position;
  Wrench wrench{{0, 0, 0}, {0, 0, 0}};
  for_each_chunk_particle(chunk.first, chunk.count, [&](std::uint32_t i) {
    wrench = wrench + particle_wrench(xyz(state.position[i]), xyz(state.interaction_force[i]), centre);
  });
  const Wrench total = BlockReduce(reduce_storage).Reduce(wrench, WrenchSum());
  const std::uint32_t first = first_chunk[chunk.rigid];
  const std::uint32_t end = first_chunk[chunk.rigid + 1];
  if (threadIdx.x == 0) {
    partial[blockIdx.x] = total;
    __threadfence();  // the partial is visible before the ticket is taken
    last = atomicAdd(&tickets[chunk.rigid], 1u) + 1u == end - first;
  }
  __syncthreads();
  if (!last) return;
  __threadfence();
  // The chunk wrenches a tile at a time: the block loads a tile together, one chunk per thread,
  // then thread 0 adds it in chunk order. (Thread 0 loading them one after another waited on L2
  // once per chunk: 245 chunks at 1M particles.)
  Wrench sum{{0, 0, 0}, {0, 0, 0}};
  for (std::uint32_t tile_first = first; tile_first < end; tile_first += kBlock) {
    const std::uint32_t c = tile_first + threadIdx.x;
    if (c < end) {
      // From L2: other blocks wrote them, and this block's L1 may not hold them yet.
      const float* w = reinterpret_cast<const float*>(partial + c);
      tile[threadIdx.x] = {{__ldcg(w), __ldcg(w + 1), __ldcg(w + 2)}, {__ldcg(w + 3), __ldcg(w + 4), __ldcg(w + 5)}};
    }
    __syncthreads();
    if (threadIdx.x == 0) {
      for (std::uint32_t k = 0; k < kBlock && tile_first + k < end; ++k) sum = sum + tile[k];
    }
    __syncthreads();
  }
  if (threadIdx.x != 0) return;
  tickets[chunk.rigid] = 0;  // ready for the next step
  RigidBody body = bodies[chunk.rigid];
  body.interaction_force = sum.force;
  body.interaction_torque = sum.torque;
  integrate_rigid_body(body, step.gravity, step.dt);
  bodies[chunk.rigid] = body;
  host_copy[chunk.rigid] = body;
}

// kChunk / kBlock blocks per chunk, a thread per particle: its particles follow the body. (One
// block per chunk left a 30k-particle body 8 blocks, each thread 16 particles one after another.)
constexpr std::uint32_t kPlaceBlocksPerChunk = kChunk / kBlock;

__global__ void rigid_place_kernel(const RigidChunk* chunks, const RigidBody* bodies, CanonicalState state,
                                   const Vec4* rest_offset) {
  __shared__ RigidBody body;
  __shared__ Mat3 rotation;
  __shared__ Vec3 omega;
  const RigidChunk chunk = chunks[blockIdx.x / kPlaceBlocksPerChunk];
  if (threadIdx.x == 0) {
    body = bodies[chunk.rigid];
    rotation = rotation_matrix(body.orientation);
    omega = angular_velocity(body);
  }
  __syncthreads();
  const std::uint32_t offset = (blockIdx.x % kPlaceBlocksPerChunk) * kBlock + threadIdx.x;
  if (offset >= chunk.count) return;
  const std::uint32_t i = chunk.first + offset;
  place_rigid_particle(body, rotation, omega, xyz(rest_offset[i]), state.position[i], state.velocity[i]);
}

}  // namespace

void launch_rigid_bodies(const FloatScene& scene, DeviceState& state, RigidBody* host_copy, cudaStream_t stream) {
  if (scene.rigid_bodies.empty()) return;
  const auto chunks = static_cast<unsigned>(state.rigid_chunks.size());
  rigid_wrench_integrate_kernel<<<chunks, kBlock, 0, stream>>>(
      state.rigid_chunks.data(), state.rigid_bodies.data(), host_copy, canonical_state(state),
      state.chunk_wrench.data(), state.first_rigid_chunk.data(), state.rigid_tickets.data(), scene.step);
  rigid_place_kernel<<<chunks * kPlaceBlocksPerChunk, kBlock, 0, stream>>>(
      state.rigid_chunks.data(), state.rigid_bodies.data(), canonical_state(state), state.rest_offset.data());
}

}  // namespace mssph::kernels
