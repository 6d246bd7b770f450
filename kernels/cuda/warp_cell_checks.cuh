#pragma once
// The density walk's cell checks shared by the lanes of a warp (step_kernels.cu's density kernel;
// tests/backends/cuda_cells_left_out_test.cu holds them to the one-lane checks).
#include "../common/fluid_physics.hpp"

#include <cooperative_groups.h>
#include <cooperative_groups/reduce.h>

#include <cstdint>

namespace mssph::kernels {

// Particle s's cells_left_out (fluid_physics.hpp) for the body `body` its sums leave out (none:
// kNoBody), checked by the warp's lanes together: lanes
// whose particles lie in one cell and leave out one body (a team's lanes, and the particles of a
// cell, ~8 at the default spacing) each check every n-th of the 27 cells' entries, n of them, and
// join their masks, where each would check all 27 on its own. Inside a large rigid or deformable
// block that check is all a particle's density walk does.
__device__ inline std::uint32_t cells_left_out_by_warp(const SortedView& v, std::uint32_t s, std::uint32_t body) {
  if (!v.grid.may_leave_out(body)) return 0;
  const Vec4 p = v.position[s];
  const std::uint64_t cell_and_body = std::uint64_t{v.grid.shape.key_of(xyz(p))} << 32 | body;
  namespace cg = cooperative_groups;
  const cg::coalesced_group alike = cg::labeled_partition(cg::coalesced_threads(), cell_and_body);
  return cg::reduce(alike, v.grid.cells_holding_only(xyz(p), body, alike.thread_rank(), alike.num_threads()),
                    cg::bit_or<std::uint32_t>());
}

}  // namespace mssph::kernels
