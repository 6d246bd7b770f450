#pragma once
// Every device array the `cuda` backend holds for a scene, in ONE list (for_each_device_array)
// that both allocates them (device_state.cu) and counts their bytes before anything is allocated
// (device_array_sizes below): the memory check and the allocation cannot disagree. No CUDA here,
// so the list is tested without a GPU.
#include "../common/list_skin.hpp"
#include "chunk_tables.hpp"
#include "contact_order.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mssph::kernels {

// A device array's first contents: a copy of a host array, `count` copies of a value, or
// `count` elements that a kernel writes before any reads them.
template <class T>
struct CopyOf {
  const std::vector<T>* host;
  std::size_t count;
};
template <class T>
CopyOf<T> copy_of(const std::vector<T>& host) {
  return {&host, host.size()};
}
template <class T>
struct Filled {
  std::size_t count;
  T value;
};
struct Uninitialised {
  std::size_t count;
};

// The arrays, each an Array<T>: DeviceBuffer<T> on the GPU (DeviceState), ArraySize<T> when
// counting.
template <template <class> class Array>
struct DeviceArrays {
  // Canonical state.
  Array<Vec4> position, velocity, interaction_force;
  Array<Vec4> rest_offset;  // empty without movable rigid bodies, whose particles alone read it
  Array<std::uint32_t> body;
  Array<std::uint8_t> fixed;
  // The neighbour grid and the cell-ordered copies.
  Array<std::uint32_t> keys, unordered_id, sorted_id, cell_count, cell_start, cell_middle;
  Array<std::uint16_t> cell_body;  // CellRanges::cell_body; empty in a scene of fluid alone
  Array<Vec4> sorted_position, sorted_velocity;
  Array<VolumePressure> volume_pressure;
  Array<Mat3> velocity_gradient;  // sorted; empty unless viscosity_model is full_stress
  // From the density pass, for the force pass (contact_order.hpp): sorted ForceWalk, the contact
  // order (one lane a particle) and its places taken.
  Array<std::uint8_t> force_walk;
  Array<std::uint32_t> contact_order, contact_taken;
  Array<std::uint32_t> block_total;  // the grid kernel's: each block's share of the cell table
  // A team's neighbour lists, one per lane, where each particle stood when they were recorded
  // (canonical order), and when to record them again (list_skin.hpp, list_check.cuh). Empty for
  // one lane per particle.
  Array<std::uint32_t> list_count, list_index;
  Array<Vec4> list_origin;
  Array<float> list_trigger2;  // per body (FloatScene::list_trigger2)
  Array<ListRefreshState> list_refresh;
  // With lists, the next step's cell-ordered copy, written where the particles move; it and
  // sorted_position, sorted_velocity trade places after each step (next_cell_order.cuh). place_of:
  // each particle's place in cell order (sorted_id's inverse), for the rigid placement.
  Array<Vec4> next_sorted_position, next_sorted_velocity;
  Array<std::uint32_t> place_of;
  // Rigid and deformable bodies (empty without them): canonical, n entries.
  Array<float> own_rest_number_density;
  // Deformable bodies (empty without them).
  Array<Vec4> elastic_force;
  Array<ElasticParameters> elastic_bodies;
  Array<std::uint32_t> deformable_body, bond_count, bond_neighbour;
  Array<Vec4> rest;
  Array<Mat3> correction;
  Array<Quat> rotation;
  Array<float> corrected_stress_action;  // K_i L_i as nine planes (mat3_store.hpp, elastic_physics.hpp)
  Array<Mat3> deformation;               // F_i
  // Bodies, the rigid-body chunk reductions and the logged sums' chunks (body_readback.cuh).
  Array<BodyParameters> bodies;
  Array<RigidBody> rigid_bodies;
  Array<RigidChunk> rigid_chunks;
  Array<std::uint32_t> first_rigid_chunk;
  Array<Wrench> chunk_wrench;
  Array<std::uint32_t> rigid_tickets;  // per rigid body: chunks done this step
  Array<BodyChunk> body_chunks;
};

// Entries of each lane's neighbour list when a team of `lanes` lanes shares each particle's
// neighbour sums (step_kernels.cu): a rebuild's density pass records them, with a skin
// (list_skin.hpp), and the passes until the next rebuild visit them instead of walking the 27 cells
// (common/neighbour_list.hpp). A particle has about 30 neighbours at h = 2 dx, 40 within h + skin,
// split over its lanes, not evenly; a list holds capacity - 1 of them, and a lane with more walks
// its share of the cells again and has the next step rebuild the grid. The capacities are twice
// the longest lists of a lattice 13 % denser than at rest (neighbour_list_test): with only one
// entry to spare, some list of a block of tens of thousands of particles overflows at nearly
// every rebuild, and the grid is rebuilt every step. One lane per particle (large scenes) keeps
// no lists: at 1M particles their 4-byte entries would more than double the fluid's 113 bytes per
// particle, and its warps load each candidate once for all 32 lanes, neighbouring particles
// walking the same cells, where lists would scatter those loads.
constexpr std::uint32_t team_list_capacity(unsigned lanes) {
  return lanes >= 8 ? 26 : lanes == 4 ? 40 : lanes == 2 ? 56 : 0;
}
inline std::size_t team_list_count(std::size_t particles, unsigned lanes) { return lanes > 1 ? particles * lanes : 0; }

// Calls visit(name, array, contents) for every array of a scene, contents being CopyOf<T>,
// Filled<T> or Uninitialised. `grid_blocks`: blocks of the grid kernel (grid_kernel_blocks, which
// needs the CUDA runtime); `team_lanes`: lanes per particle of the neighbour sums (choose_team_lanes).
template <template <class> class Array, class Visit>
void for_each_device_array(DeviceArrays<Array>& a, const FloatScene& scene, const ChunkTables& chunks,
                           std::size_t grid_blocks, unsigned team_lanes, Visit&& visit) {
  const std::size_t n = scene.position.size();
  const std::size_t cell_table = std::size_t{scene.grid.cell_count()} + 1;
  const Vec4 zero{0, 0, 0, 0};
  visit("position", a.position, copy_of(scene.position));
  visit("velocity", a.velocity, copy_of(scene.velocity));
  visit("interaction_force", a.interaction_force, Filled<Vec4>{n, zero});
  // Read only to place movable rigid bodies' particles (rigid_bodies.cu).
  visit("rest_offset", a.rest_offset, CopyOf<Vec4>{&scene.rest_offset, scene.rigid_bodies.empty() ? 0 : n});
  const std::size_t deformables = scene.deformable_body.size();
  if (deformables > 0) {
    visit("elastic_force", a.elastic_force, Filled<Vec4>{n, zero});
    visit("elastic_bodies", a.elastic_bodies, copy_of(scene.elastic_bodies));
    visit("deformable_body", a.deformable_body, copy_of(scene.deformable_body));
    visit("bond_count", a.bond_count, copy_of(scene.bond_count));
    visit("bond_neighbour", a.bond_neighbour, copy_of(scene.bond_neighbour));
    visit("rest", a.rest, copy_of(scene.rest));
    visit("correction", a.correction, copy_of(scene.correction));
    visit("rotation", a.rotation, Filled<Quat>{deformables, Quat{0, 0, 0, 1}});
    visit("corrected_stress_action", a.corrected_stress_action, Uninitialised{9 * deformables});
    // Identity until the first step: the logged volume ratio of the rest state is 1.
    visit("deformation", a.deformation, Filled<Mat3>{deformables, identity_mat3()});
  }
  visit("body", a.body, copy_of(scene.body));
  visit("fixed", a.fixed, copy_of(scene.fixed));
  visit("keys", a.keys, Uninitialised{n});
  visit("unordered_id", a.unordered_id, Uninitialised{n});  // a cell's particles in the order they took its slots
  // Zero until the first rebuild: the check before it (list_skin.hpp) reads the ids it copies by.
  visit("sorted_id", a.sorted_id, Filled<std::uint32_t>{n, 0u});
  // Zero at the start; the slot kernel takes every count back to zero for the next step.
  visit("cell_count", a.cell_count, Filled<std::uint32_t>{cell_table, 0u});
  visit("cell_start", a.cell_start, Uninitialised{cell_table});
  // CellRanges::cell_middle: every rebuild writes every entry (the scan, then each non-empty cell's).
  visit("cell_middle", a.cell_middle, Uninitialised{cell_table});
  visit("own_rest_number_density", a.own_rest_number_density, copy_of(scene.own_rest_number_density));
  // Where particles take their own body at rest, their walks leave out its rows (CellRanges): each
  // rebuild writes the entries of the non-empty cells, the only ones read.
  const bool rows_left_out = !scene.own_rest_number_density.empty();
  visit("cell_body", a.cell_body, Uninitialised{rows_left_out ? cell_table : 0});
  visit("sorted_position", a.sorted_position, Uninitialised{n});
  visit("sorted_velocity", a.sorted_velocity, Uninitialised{n});
  visit("volume_pressure", a.volume_pressure, Filled<VolumePressure>{n, VolumePressure{0, 0}});
  // The velocity-gradient pass writes every particle's, after the density pass and before the force pass.
  visit("velocity_gradient", a.velocity_gradient, Uninitialised{scene.full_stress_viscosity ? n : 0});
  // The density pass writes every particle's walk, and the places it takes after launch_densities
  // clears the count.
  visit("force_walk", a.force_walk, Uninitialised{n});
  const std::size_t contact_capacity = contact_order_capacity(scene, team_lanes);
  visit("contact_order", a.contact_order, Uninitialised{contact_capacity});
  visit("contact_taken", a.contact_taken, Uninitialised{contact_capacity > 0 ? 1u : 0u});
  visit("block_total", a.block_total, Uninitialised{grid_blocks});
  // Written by the density pass before the force pass reads them, for every particle that receives forces.
  const std::size_t lists = team_list_count(n, team_lanes);
  visit("list_count", a.list_count, Uninitialised{lists});
  visit("list_index", a.list_index, Uninitialised{lists * team_list_capacity(team_lanes)});
  const bool listing = lists > 0;
  visit("list_origin", a.list_origin, Filled<Vec4>{listing ? n : 0, zero});
  visit("list_trigger2", a.list_trigger2,
        CopyOf<float>{&scene.list_trigger2, listing ? scene.list_trigger2.size() : 0});
  // A rebuild requested: the first step has no lists yet.
  visit("list_refresh", a.list_refresh, Filled<ListRefreshState>{listing ? 1u : 0u, ListRefreshState{1, 0, 0, 0}});
  // The force pass writes every particle's before the next step reads them; each rebuild, every
  // particle's place.
  visit("next_sorted_position", a.next_sorted_position, Uninitialised{listing ? n : 0});
  visit("next_sorted_velocity", a.next_sorted_velocity, Uninitialised{listing ? n : 0});
  visit("place_of", a.place_of, Uninitialised{listing && !scene.rigid_bodies.empty() ? n : 0});
  visit("bodies", a.bodies, copy_of(scene.bodies));
  visit("rigid_bodies", a.rigid_bodies, copy_of(scene.rigid_bodies));
  visit("rigid_chunks", a.rigid_chunks, copy_of(chunks.rigid));
  visit("first_rigid_chunk", a.first_rigid_chunk, copy_of(chunks.first_rigid_chunk));
  visit("chunk_wrench", a.chunk_wrench, Uninitialised{chunks.rigid.size()});
  // Zero at the start; the block that takes a body's last ticket sets it back to zero.
  visit("rigid_tickets", a.rigid_tickets, Filled<std::uint32_t>{scene.rigid_bodies.size(), 0u});
  visit("body_chunks", a.body_chunks, copy_of(chunks.body));
}

// The size of one array, for counting before allocating.
template <class T>
struct ArraySize {
  std::size_t count = 0;
  std::size_t bytes() const { return count * sizeof(T); }
};

struct DeviceArraySizes {
  DeviceArrays<ArraySize> arrays;
  std::size_t total_bytes = 0;
};

inline DeviceArraySizes device_array_sizes(const FloatScene& scene, const ChunkTables& chunks, std::size_t grid_blocks,
                                           unsigned team_lanes) {
  DeviceArraySizes sizes;
  for_each_device_array(sizes.arrays, scene, chunks, grid_blocks, team_lanes,
                        [&](const char*, auto& array, const auto& contents) {
                          array.count = contents.count;
                          sizes.total_bytes += array.bytes();
                        });
  return sizes;
}

}  // namespace mssph::kernels
