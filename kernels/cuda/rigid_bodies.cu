#include "rigid_bodies.cuh"

#include "chunk_particles.cuh"
#include "dependent_launch.cuh"
#include "list_check.cuh"
#include "next_cell_order.cuh"

#include <cub/cub.cuh>
#include <cuda/atomic>

namespace mssph::kernels {
namespace {

struct WrenchSum {
  __device__ Wrench operator()(const Wrench& a, const Wrench& b) const { return a + b; }
};

// Loads chunk wrench c from L2: other blocks wrote it, and this block's L1 may not hold it yet.
__device__ Wrench load_chunk_wrench(const Wrench* partial, std::uint32_t c) {
  const float* w = reinterpret_cast<const float*>(partial + c);
  return {{__ldcg(w), __ldcg(w + 1), __ldcg(w + 2)}, {__ldcg(w + 3), __ldcg(w + 4), __ldcg(w + 5)}};
}

// One block per chunk (chunk_tables.hpp), thread t taking its particles t, t + kBlock, ... in
// order (for_each_chunk_particle): the wrench of the chunk's interaction forces about the body's
// centre. The block that finishes a body's last chunk (a ticket counter tells; the add that takes
// the ticket publishes the block's partial and sees every earlier block's; the block barrier after
// it orders the other threads' loads of the partials after that add) then adds the body's chunk
// wrenches, thread t those of chunks t, t + kBlock, ... in order and CUB's block tree
// the threads' sums, and integrates the body (eq. 8, 9): which block does it varies, the sums'
// order does not, so runs repeat bit for bit. The body goes to `host_copy` too.
__global__ void rigid_wrench_integrate_kernel(const RigidChunk* chunks, RigidBody* bodies, RigidBody* host_copy,
                                              CanonicalState state, Wrench* partial, const std::uint32_t* first_chunk,
                                              std::uint32_t* tickets, StepParameters step) {
  // Loaded while the force kernel may still run (dependent_launch.cuh): the chunk tables are set
  // at upload, the body by this kernel a step before. Thread 0 loads the whole body now, so the
  // last block does not wait for it after its sums.
  const RigidChunk chunk = chunks[blockIdx.x];
  const Vec3 centre = bodies[chunk.rigid].position;
  RigidBody body{};
  if (threadIdx.x == 0) body = bodies[chunk.rigid];
  const std::uint32_t first = first_chunk[chunk.rigid];
  const std::uint32_t end = first_chunk[chunk.rigid + 1];
  follow_previous_kernel();
  using BlockReduce = cub::BlockReduce<Wrench, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  __shared__ bool last;
  Wrench wrench{{0, 0, 0}, {0, 0, 0}};
  for_each_chunk_particle(chunk.first, chunk.count, [&](std::uint32_t i) {
    wrench = wrench + particle_wrench(xyz(state.position[i]), xyz(state.interaction_force[i]), centre);
  });
  const Wrench total = BlockReduce(reduce_storage).Reduce(wrench, WrenchSum());
  if (threadIdx.x == 0) {
    partial[blockIdx.x] = total;
    cuda::atomic_ref<std::uint32_t, cuda::thread_scope_device> ticket(tickets[chunk.rigid]);
    last = ticket.fetch_add(1u, cuda::memory_order_acq_rel) + 1u == end - first;
  }
  __syncthreads();
  if (!last) return;
  Wrench share{{0, 0, 0}, {0, 0, 0}};
#pragma unroll 4  // loads in flight together; a body has more than kBlock chunks only above ~1M particles
  for (std::uint32_t c = first + threadIdx.x; c < end; c += kBlock) share = share + load_chunk_wrench(partial, c);
  __syncthreads();  // reduce_storage is reused
  const Wrench sum = BlockReduce(reduce_storage).Reduce(share, WrenchSum());
  if (threadIdx.x != 0) return;
  tickets[chunk.rigid] = 0;  // ready for the next step
  body.interaction_force = sum.force;
  body.interaction_torque = sum.torque;
  integrate_rigid_body(body, step.gravity, step.dt);
  bodies[chunk.rigid] = body;
  host_copy[chunk.rigid] = body;
}

// A block per stride of kBlock particles of a chunk (blockIdx.y), a thread per particle: its
// particles follow the body, and with lists each is checked against its trigger for the next step
// (ListCheck) and written in cell order for it (NextCellOrder). A small body's few chunks thus
// spread over many blocks, not over a few threads that each place many particles one after
// another.
__global__ void rigid_place_kernel(const RigidChunk* chunks, const RigidBody* bodies, CanonicalState state,
                                   const Vec4* rest_offset, const std::uint32_t* body_of_particle, ListCheck check,
                                   NextCellOrder next) {
  // Loaded while the wrench kernel may still run (dependent_launch.cuh): chunks, rest offsets and
  // bodies of particles are set at upload, the places in cell order by the grid kernel.
  const RigidChunk chunk = chunks[blockIdx.x];
  const std::uint32_t offset = blockIdx.y * kBlock + threadIdx.x;
  const bool places = offset < chunk.count;
  const std::uint32_t i = chunk.first + offset;
  const bool lists = check.active();
  const std::uint32_t particle_body = places && lists ? body_of_particle[i] : 0u;
  const std::uint32_t place = places && next.active() ? next.place_of[i] : 0u;
  const Vec3 rest = places ? xyz(rest_offset[i]) : Vec3{0, 0, 0};
  follow_previous_kernel();
  __shared__ RigidBody body;
  __shared__ Mat3 rotation;
  __shared__ Vec3 omega;
  if (threadIdx.x == 0) {
    body = bodies[chunk.rigid];
    rotation = rotation_matrix(body.orientation);
    omega = angular_velocity(body);
  }
  __syncthreads();
  Vec4 position{0, 0, 0, 0};
  Vec4 velocity{0, 0, 0, 0};
  if (places) {
    place_rigid_particle(body, rotation, omega, rest, position, velocity);
    state.position[i] = position;
    state.velocity[i] = velocity;
    if (next.active()) next.put(place, particle_body, xyz(position), velocity);
  }
  if (lists) check.note(places, i, particle_body, xyz(position));
}

}  // namespace

void launch_rigid_bodies(const FloatScene& scene, const ChunkTables& chunks, DeviceState& state, RigidBody* host_copy,
                         cudaStream_t stream) {
  if (scene.rigid_bodies.empty()) return;
  const auto blocks = static_cast<unsigned>(chunks.rigid.size());
  launch_after_previous(rigid_wrench_integrate_kernel, blocks, kBlock, stream, "launch the rigid bodies' dynamics",
                        state.rigid_chunks.data(), state.rigid_bodies.data(), host_copy, canonical_state(state),
                        state.chunk_wrench.data(), state.first_rigid_chunk.data(), state.rigid_tickets.data(),
                        scene.step);
  launch_after_previous(rigid_place_kernel, dim3(blocks, chunks.rigid_chunk_strides), kBlock, stream,
                        "launch the rigid particles' placement", state.rigid_chunks.data(), state.rigid_bodies.data(),
                        canonical_state(state), state.rest_offset.data(), state.body.data(), list_check(state),
                        next_cell_order(state));
}

}  // namespace mssph::kernels
