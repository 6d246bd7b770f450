#include "step_kernels.cuh"

#include "../common/fluid_physics.hpp"
#include "../common/list_skin.hpp"
#include "contact_order.cuh"
#include "dependent_launch.cuh"
#include "list_check.cuh"
#include "next_cell_order.cuh"
#include "thread_blocks.cuh"
#include "warp_cell_checks.cuh"

#include <algorithm>
#include <type_traits>

namespace mssph::kernels {
namespace {

// The neighbour sums give each particle a team of Lanes consecutive lanes of a warp (1 to 8,
// see team_lanes.hpp): the lanes split its candidates (CellRanges::for_each_candidate) and add
// their partial sums by shuffles in a fixed order, so a sum's order depends only on Lanes. Every
// lane ends with the same bits: at each xor stage the two partners add the same two values, in
// swapped order, and float addition is commutative.
// This thread's seat: the particle (or deformable particle) its team serves, and its lane.
struct TeamSeat {
  std::uint32_t member;
  std::uint32_t lane;
};
template <unsigned Lanes>
__device__ TeamSeat team_seat() {
  const std::uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  return {thread / Lanes, thread % Lanes};
}

template <unsigned Lanes>
__device__ float team_sum(float x) {
  for (unsigned offset = 1; offset < Lanes; offset *= 2) x += __shfl_xor_sync(0xffffffffu, x, offset);
  return x;
}
template <unsigned Lanes>
__device__ std::uint32_t team_sum(std::uint32_t x) {
  for (unsigned offset = 1; offset < Lanes; offset *= 2) x += __shfl_xor_sync(0xffffffffu, x, offset);
  return x;
}
template <unsigned Lanes>
__device__ float team_min(float x) {
  for (unsigned offset = 1; offset < Lanes; offset *= 2) x = fminf(x, __shfl_xor_sync(0xffffffffu, x, offset));
  return x;
}
template <unsigned Lanes>
__device__ Vec3 team_sum(Vec3 v) {
  return {team_sum<Lanes>(v.x), team_sum<Lanes>(v.y), team_sum<Lanes>(v.z)};
}

template <unsigned Lanes>
__device__ Mat3 team_sum(const Mat3& a) {
  Mat3 sum;
  for (int k = 0; k < 9; ++k) sum.m[k] = team_sum<Lanes>(a.m[k]);
  return sum;
}
template <unsigned Lanes>
__device__ BondSums team_sum(const BondSums& s) {
  return {team_sum<Lanes>(s.moment), team_sum<Lanes>(s.current_gradient), team_sum<Lanes>(s.rest_gradient)};
}

// The deformable passes split each particle's bonds over a team the same way. The rest of step 1
// (store_rotation_and_stress: the rotation's iterations, the stress) is serial per particle: the
// teams hand their sums through shared memory to one thread per particle, so a warp runs it for
// 32 particles at once rather than for its 32 / Lanes teams with the other lanes idle. Viscous:
// the scene has a body with a viscous modulus, whose particles also sum their velocities in the
// same pass over their bonds; a scene without one runs the kernel without that sum, its
// registers, shuffles and shared memory.
// Both bond passes wait mostly on their gathers of neighbour data, so they are held to 64
// registers, four blocks a multiprocessor: the warps this adds hide more of those loads than the
// few spilled values of the viscous variant and the rotation's Newton steps cost.
inline constexpr int kBondBlocksPerMultiprocessor = 4;

template <unsigned Lanes, bool Viscous>
__global__ void __launch_bounds__(kBlock, kBondBlocksPerMultiprocessor)
    rotation_stress_kernel(DeviceDeformableView view) {
  // Its reads (positions and velocities of the last step, rest bonds, last step's rotations) and
  // writes (rotations, stresses, deformation gradients) are none of the grid's and density pass's,
  // which may still run: it works at once and waits at its end (dependent_launch.cuh).
  let_next_kernel_be_scheduled();
  const TeamSeat seat = team_seat<Lanes>();
  const std::uint32_t d = seat.member, lane = seat.lane;
  const bool active = d < view.count;
  const bool viscous = Viscous && active && view.bodies[view.body_of[d]].retardation_time > 0.0f;
  BondSums sums{zero_mat3(), zero_mat3(), zero_mat3()};
  Mat3 velocity_sum = zero_mat3();
  if (viscous) {
    sums = bond_sums_share(view, d, lane, Lanes, &velocity_sum);
  } else if (active) {
    sums = bond_sums_share(view, d, lane, Lanes);
  }
  sums = team_sum<Lanes>(sums);
  if constexpr (Viscous) velocity_sum = team_sum<Lanes>(velocity_sum);
  if constexpr (Lanes == 1) {
    if (active) store_rotation_and_stress(view, d, sums);
    if (viscous) add_viscous_stress(view, d, velocity_sum);
  } else {
    constexpr unsigned kTeams = kBlock / Lanes;  // the block's particles
    __shared__ BondSums team_sums[kTeams];
    __shared__ Mat3 team_velocity_sums[Viscous ? kTeams : 1];
    if (lane == 0) {
      team_sums[threadIdx.x / Lanes] = sums;
      if constexpr (Viscous) team_velocity_sums[threadIdx.x / Lanes] = velocity_sum;
    }
    __syncthreads();
    const std::uint32_t particle = blockIdx.x * kTeams + threadIdx.x;
    if (threadIdx.x < kTeams && particle < view.count) {
      store_rotation_and_stress(view, particle, team_sums[threadIdx.x]);
      if constexpr (Viscous) {
        if (view.bodies[view.body_of[particle]].retardation_time > 0.0f)
          add_viscous_stress(view, particle, team_velocity_sums[threadIdx.x]);
      }
    }
  }
  wait_for_previous_kernel();
}

template <unsigned Lanes>
__global__ void __launch_bounds__(kBlock, kBondBlocksPerMultiprocessor)
    elastic_force_kernel(DeviceDeformableView view) {
  follow_previous_kernel();
  const TeamSeat seat = team_seat<Lanes>();
  const std::uint32_t d = seat.member, lane = seat.lane;
  const bool active = d < view.count;
  Vec3 force{0, 0, 0};
  if (active) force = elastic_force_share(view, d, lane, Lanes);
  force = team_sum<Lanes>(force);
  if (active && lane == 0) store_elastic_force(view, d, force);
}

// Threads per block of the density and force kernels: half of kBlock. A block holds its share of
// the multiprocessor until its slowest warp is done, and a one-lane walk's length varies from
// warp to warp, so smaller blocks give their share back sooner (the register caps below count
// threads per multiprocessor, whatever the block size).
inline constexpr int kSumBlock = 128;

// Threads of the density kernel that must fit on a multiprocessor at once, which caps its
// registers as for the force kernel (kForceThreadsPerMultiprocessor). One lane's walk (split
// cells, the warp's shared cell checks, the walk by segments) gets 48 registers at 1280, a few
// bytes spilled: a lower cap spills more of the walk, a higher one leaves fewer warps to hide its
// loads. Teams compile to 32 registers, which 2048 threads allow.
constexpr int density_threads_per_multiprocessor(unsigned lanes) { return lanes == 1 ? 1280 : 2048; }

// The body whose candidates particle s's density sums leave out, taken at rest (density_sum_over):
// its body_left_out, but none for a boundary particle whose warp holds a fluid one, which sums its
// own wall live so that the warp's lanes take one walk together: by segments with one lane
// (walks_by_segments), over lists that hold its wall with teams. A warp holds the same particles
// from one rebuild to the next, so a team's lists hold the wall on exactly the steps its sums take
// it. Boundary particles whose warp holds no fluid one (inside a wall, or beside a rigid or
// deformable block) leave out their wall, as rigid and deformable particles their body. Called by
// every lane of the warp.
__device__ std::uint32_t density_body_left_out(const SortedView& view, std::uint32_t s, bool active) {
  const std::uint32_t body = active ? body_of(view.position[s]) : kNoBody;
  const bool beside_fluid = __any_sync(0xffffffffu, active && takes_near_notes(view.bodies[body]));
  if (!active || (beside_fluid && walks_with_fluid(view.bodies[body]))) return kNoBody;
  return body_left_out(view.bodies[body], body);
}

// Whether particle s's one-lane density walk goes a segment at a time (density_sum_noting_near):
// with near notes, one that leaves out no body (`own`): a fluid particle's, which notes its near
// candidates, and a boundary particle's beside it. For a fluid particle the walk is the plain
// one's, candidate for candidate, so either gives the same bits.
__device__ bool walks_by_segments(const NearNotes& notes, std::uint32_t own) { return notes.taken() && own == kNoBody; }

// A team's lane, on a step that rebuilt the grid, records the candidates of its share within
// h + skin in its list (lists: one per thread), for the force pass and the steps until the next
// rebuild, and asks for the next step to rebuild if the list overflowed; on the other steps it
// sums over that list. One lane alone records none and walks every step (device_arrays.hpp,
// team_list_capacity, says why); for a fluid particle it notes which candidates lie within h, for
// the force pass, when the pass is given notes (near_notes.hpp). Every particle also records
// whether another body lies within h of it (taken by rigid and deformable particles only:
// DensitySum::nearest_other_body2), for the force pass to skip the walk of those without one
// (contact_order.hpp).
template <unsigned Lanes>
__global__ void __launch_bounds__(kSumBlock, density_threads_per_multiprocessor(Lanes) / kSumBlock)
    density_kernel(SortedView view, VolumePressure* volume_pressure, ForceWalks walks, NeighbourLists lists,
                   ListRefreshState* refresh, float record_radius2, NearNotes notes) {
  follow_previous_kernel();
  const TeamSeat seat = team_seat<Lanes>();
  const std::uint32_t s = seat.member, lane = seat.lane;
  const bool active = s < view.step.particle_count;
  DensitySum sum{0.0f, 0.0f};
  const std::uint32_t own = density_body_left_out(view, s, active);
  if (active) {
    if constexpr (Lanes > 1) {
      const std::uint32_t list = blockIdx.x * blockDim.x + threadIdx.x;
      if (refresh->recorded) {
        sum = density_sum_recording(view, s, lane, Lanes, cells_left_out_by_warp(view, s, own), lists, list,
                                    record_radius2, own);
        if (lists.count[list] >= lists.capacity) refresh->requested = 1;
      } else {
        sum = density_sum_listed(view, s, lane, Lanes, lists, list, own);
      }
    } else if (walks_by_segments(notes, own)) {
      sum = density_sum_noting_near(view, s, view.id[s], notes);
    } else {
      sum = density_sum(view, s, lane, Lanes, cells_left_out_by_warp(view, s, own), own);
    }
  }
  sum.delta = team_sum<Lanes>(sum.delta);
  sum.nearest_other_body2 = team_min<Lanes>(sum.nearest_other_body2);
  if (active && lane == 0) volume_pressure[s] = density_from(sum, view, s, own).volume_pressure;
  record_force_walk(walks, view, s, active && lane == 0, sum.nearest_other_body2 < view.step.smoothing.h2);
}

// For the full_stress viscosity, each fluid particle's velocity gradient after the density pass,
// which gave the volumes it reads (velocity_gradient_sums_over): a team's lanes over the lists that
// pass recorded or visited, one lane alone over the 27 cells; stored in cell order for the force
// pass.
template <unsigned Lanes>
__global__ void __launch_bounds__(kSumBlock)
    velocity_gradient_kernel(SortedView view, Mat3* velocity_gradient, NeighbourLists lists) {
  follow_previous_kernel();
  const TeamSeat seat = team_seat<Lanes>();
  const std::uint32_t s = seat.member, lane = seat.lane;
  const bool active = s < view.step.particle_count;
  VelocityGradientSums sums = zero_velocity_gradient_sums();
  if (active) {
    const Vec3 x = xyz(view.position[s]);
    if constexpr (Lanes > 1) {
      const std::uint32_t list = blockIdx.x * blockDim.x + threadIdx.x;
      sums = velocity_gradient_sums_over(view, s, listed_share(view.grid, x, lane, Lanes, lists, list));
    } else {
      sums = velocity_gradient_sums_over(view, s, [&](auto&& visit) { view.grid.for_each_candidate(x, visit); });
    }
  }
  sums = {team_sum<Lanes>(sums.velocity_moment), team_sum<Lanes>(sums.position_moment)};
  if (active && lane == 0) velocity_gradient[s] = sums.gradient();
}

// Threads of the force kernel that must fit on a multiprocessor at once, which caps its registers
// at 65536 / threads, rounded down to a multiple of 8. One lane per particle (large scenes) holds
// its walk's segments in shared memory (SharedHeldSegments, 96 bytes a thread), which the
// multiprocessor takes from its L1: at 1024 threads the walk has 64 registers and no spills, and
// L1 keeps room for the candidates' loads; more threads spill registers into a smaller L1. Teams
// of lanes (small scenes) compile to 64 registers anyway.
inline constexpr int kForceThreadsPerMultiprocessor = 1024;

// The segments a one-lane force walk holds (HeldSegments) in the block's shared memory, a column
// per thread: a thread's column lies in bank threadIdx.x mod 32, so a warp's lanes never share a
// bank, whatever segment each is at.
struct SharedHeldSegments {
  static constexpr std::uint32_t capacity = kHeldSegments;
  std::uint32_t (*first_)[kSumBlock];
  std::uint32_t (*near_)[kSumBlock];

  __device__ void put(std::uint32_t k, std::uint32_t first, std::uint32_t near) {
    first_[k][threadIdx.x] = first;
    near_[k][threadIdx.x] = near;
  }
  __device__ std::uint32_t first(std::uint32_t k) const { return first_[k][threadIdx.x]; }
  __device__ std::uint32_t near(std::uint32_t k) const { return near_[k][threadIdx.x]; }
};

// A team serves the particle of its force_seat: those in cell order that hold no place in the
// contact order, then those that do (contact_order.hpp).
// Teams, which keep lists, check each particle they advance against its trigger for the next step
// (ListCheck) and write it in cell order for the next step (NextCellOrder).
// After the elastic pass (`after_elastic_forces`), whose one write, the elastic forces, only the
// leap-frog reads, a team sums first and waits after: what the sums read was written by kernels
// that finished before the elastic pass was scheduled (dependent_launch.cuh), so the force pass
// runs beside the elastic one.
template <unsigned Lanes, bool FullStress>
__global__ void __launch_bounds__(kSumBlock, kForceThreadsPerMultiprocessor / kSumBlock)
    forces_kernel(SortedView view, CanonicalState state, ForceWalks walks, NeighbourLists lists, NearNotes notes,
                  ListCheck check, NextCellOrder next, bool after_elastic_forces) {
  if (!after_elastic_forces) follow_previous_kernel();
  const TeamSeat team = team_seat<Lanes>();
  const ForceSeat seat = force_seat(view, walks, team.member);
  const std::uint32_t s = seat.s, lane = team.lane;
  const bool active = seat.active;
  ForceSum sum = zero_force_sum();
  // A team's lane visits the list of its last rebuild (density_kernel) instead of walking its share
  // of the 27 cells again; one lane alone (large scenes) has no lists (density_kernel) and walks,
  // a fluid particle over the near notes its density walk took, when the pass has them.
  // Neither walks for a rigid or deformable particle with no other body within h: its sums are zero.
  constexpr bool kTeam = Lanes > 1;
  const std::uint32_t list = s * Lanes + lane;
  ForceParticle particle{};
  std::uint32_t i = 0;  // canonical index, loaded before the sum so that the leap-frog does not wait for it
  if (active) {
    i = view.id[s];
    particle = load_force_particle(view, s);
    if (seat.walks) {
      if constexpr (kTeam) {
        sum = force_sum_listed<FullStress>(view, particle, lane, Lanes, lists, list);
      } else {
        __shared__ std::uint32_t held_first[kHeldSegments][kSumBlock], held_near[kHeldSegments][kSumBlock];
        SharedHeldSegments held{held_first, held_near};
        sum = force_sum<FullStress>(view, particle, i, notes, held);
      }
    }
  }
  sum = {team_sum<Lanes>(sum.pressure), team_sum<Lanes>(sum.viscosity), team_sum<Lanes>(sum.interaction),
         team_min<Lanes>(sum.nearest_boundary2)};
  if (after_elastic_forces) follow_previous_kernel();
  // apply_forces split over the team: every lane advances the particle from the same team sum
  // (same bits), tests its list again (one lane: every candidate around the new position) for a
  // wall, and the team counts the lanes that found one; lane 0 then rejects the move if any did
  // (its one-lane velocity projection, rare) and stores.
  Advance advance{};
  std::uint32_t lanes_touching_wall = 0;
  if (active) {
    advance = advance_particle(view.step, state, particle, i, sum);
    const bool touches = kTeam ? wall_check_share(view, advance, lane, Lanes, lists, list)
                               : wall_check_share(view, advance, lane, Lanes);
    lanes_touching_wall = touches ? 1u : 0u;
  }
  lanes_touching_wall = team_sum<Lanes>(lanes_touching_wall);
  const bool stores = active && lane == 0;
  if (stores) store_advance(view, state, sum, advance, lanes_touching_wall > 0);
  if (kTeam && stores && next.active()) {
    if (advance.integrates) {
      next.put(s, particle.body, xyz(advance.position), advance.velocity);
    } else {
      next.put(s, particle.body, particle.x, make_vec4(particle.u, particle.position_carry));
    }
  }
  if (kTeam && check.active())
    check.note(stores && advance.integrates, advance.i, particle.body, xyz(advance.position));
}

// Calls launch(std::integral_constant<unsigned, L>) for the team size L = lanes, so each launch
// site names its kernel once.
template <class Launch>
void with_team_lanes(unsigned lanes, Launch&& launch) {
  switch (lanes) {
    case 8:
      launch(std::integral_constant<unsigned, 8>{});
      break;
    case 4:
      launch(std::integral_constant<unsigned, 4>{});
      break;
    case 2:
      launch(std::integral_constant<unsigned, 2>{});
      break;
    default:
      launch(std::integral_constant<unsigned, 1>{});
      break;
  }
}

}  // namespace

bool launch_elasticity(const FloatScene& scene, DeviceState& state, unsigned team_lanes, cudaStream_t stream) {
  const DeviceDeformableView view = deformable_view(scene, state);
  if (view.count == 0) return false;
  const bool viscous = std::any_of(scene.elastic_bodies.begin(), scene.elastic_bodies.end(),
                                   [](const ElasticParameters& body) { return body.retardation_time > 0.0f; });
  with_team_lanes(team_lanes, [&](auto lanes) {
    constexpr unsigned L = decltype(lanes)::value;
    const unsigned blocks = blocks_for(std::size_t{view.count} * L);
    launch_after_previous(viscous ? rotation_stress_kernel<L, true> : rotation_stress_kernel<L, false>, blocks, kBlock,
                          stream, "launch the rotations", view);
    launch_after_previous(elastic_force_kernel<L>, blocks, kBlock, stream, "launch the elastic forces", view);
  });
  return true;
}

void launch_densities(const FloatScene& scene, DeviceState& state, unsigned team_lanes, const NearNotes& notes,
                      cudaStream_t stream) {
  const std::size_t n = state.position.size();
  const ForceWalks walks = force_walks(state);
  if (walks.contact_capacity > 0)
    cuda_check(cudaMemsetAsync(walks.contact_taken, 0, sizeof(std::uint32_t), stream), "clear the contact order");
  with_team_lanes(team_lanes, [&](auto lanes) {
    constexpr unsigned L = decltype(lanes)::value;
    launch_after_previous(density_kernel<L>, blocks_for(n * L, kSumBlock), kSumBlock, stream, "launch the densities",
                          sorted_view(scene, state), state.volume_pressure.data(), walks, team_lists(state, L),
                          state.list_refresh.data(), list_skin(scene.step.smoothing.h).record_radius2, notes);
    if (scene.full_stress_viscosity) {
      launch_after_previous(velocity_gradient_kernel<L>, blocks_for(n * L, kSumBlock), kSumBlock, stream,
                            "launch the velocity gradients", sorted_view(scene, state), state.velocity_gradient.data(),
                            team_lists(state, L));
    }
  });
}

void launch_forces(const FloatScene& scene, DeviceState& state, unsigned team_lanes, const NearNotes& notes,
                   bool after_elastic_forces, cudaStream_t stream) {
  const ForceWalks walks = force_walks(state);
  const std::size_t teams = state.position.size() + walks.contact_capacity;
  with_team_lanes(team_lanes, [&](auto lanes) {
    constexpr unsigned L = decltype(lanes)::value;
    launch_after_previous(scene.full_stress_viscosity ? forces_kernel<L, true> : forces_kernel<L, false>,
                          blocks_for(teams * L, kSumBlock), kSumBlock, stream, "launch the forces",
                          sorted_view(scene, state), canonical_state(state), walks, team_lists(state, L), notes,
                          list_check(state), next_cell_order(state), after_elastic_forces);
  });
}

cudaError_t step_kernels_loadable() {
  cudaFuncAttributes attributes{};
  return cudaFuncGetAttributes(&attributes, density_kernel<1>);
}

}  // namespace mssph::kernels
