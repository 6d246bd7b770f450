#include "neighbour_grid.cuh"

#include "../common/fluid_physics.hpp"
#include "../common/list_skin.hpp"
#include "thread_blocks.cuh"

#include <cub/cub.cuh>

namespace mssph::kernels {
namespace {

// The neighbour grid by a counting sort, stable like a sort of (key, index) pairs (the cpu
// backend's order), so every run lays the particles out alike. Three kernels and a CUB scan:
// 1. each particle's cell key, and a count per cell (integer atomics: the counts, not their
//    order, are kept);
// 2. an exclusive scan of the counts: the cell table, cell_start[k] = particles in cells below k;
// 3. each particle takes a slot in its cell's range (atomically, in no fixed order), writes its
//    index there and gives back its count, so the counts are zero again for the next step; then
// 4. each particle counts the particles of its cell with a smaller index in those slots: its rank
//    in the canonical order within the cell, so its place in cell order, where it copies itself.
//    (A thread per cell sorting its slots, as before, was serial per cell: 62 of the 123 us of
//    the grid at 1M particles on an H100.)
__global__ void cell_count_kernel(const Vec4* position, std::uint32_t n, GridShape grid, std::uint32_t* keys,
                                  std::uint32_t* cell_count) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = grid.key_of(xyz(position[i]));
  keys[i] = key;
  atomicAdd(&cell_count[key], 1u);
}

__global__ void cell_slot_kernel(const std::uint32_t* keys, std::uint32_t n, const std::uint32_t* cell_start,
                                 std::uint32_t* cell_count, std::uint32_t* unordered_id) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = keys[i];
  unordered_id[cell_start[key] + atomicSub(&cell_count[key], 1u) - 1u] = i;
}

struct CellOrder {
  const std::uint32_t* keys;
  const std::uint32_t* cell_start;
  const std::uint32_t* unordered_id;
  const Vec4* position;
  const Vec4* velocity;
  const std::uint32_t* body;
  std::uint32_t* sorted_id;
  Vec4* sorted_position;
  Vec4* sorted_velocity;
};

// The teams' lists (list_skin.hpp): where each sorted particle stood at the last rebuild, and the
// state of their refresh. Null pointers without lists.
struct ListOrigin {
  Vec4* origin;
  ListRefreshState* refresh;
};

// With lists, a rebuild also records where each particle stands, marks the step as one whose
// density pass records the lists, and takes back the request that caused it.
__global__ void cell_rank_kernel(std::uint32_t n, CellOrder order, ListOrigin lists) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (lists.refresh && i == 0) {
    lists.refresh->recorded = 1;
    lists.refresh->requested = 0;
    ++lists.refresh->rebuilds;
  }
  if (i >= n) return;
  const std::uint32_t key = order.keys[i];
  const std::uint32_t first = order.cell_start[key];
  const std::uint32_t end = order.cell_start[key + 1];
  std::uint32_t rank = 0;
  for (std::uint32_t slot = first; slot < end; ++slot) rank += order.unordered_id[slot] < i ? 1u : 0u;
  const std::uint32_t s = first + rank;
  order.sorted_id[s] = i;
  place_in_cell_order(s, i, order.position, order.velocity, order.body, order.sorted_position, order.sorted_velocity);
  if (lists.origin) lists.origin[s] = order.sorted_position[s];
}

// A step's start with lists: every particle is copied into the cell order of the last rebuild
// and checked against the trigger (list_skin.hpp); the block that finishes last sets `rebuild`,
// the condition of the graph's node that holds the grid's kernels (launch_neighbour_grid), when a
// particle moved past it or a rebuild was requested. One thread sets it: concurrent calls of cudaGraphSetConditional
// are undefined.
__global__ void list_check_kernel(std::uint32_t n, CellOrder order, ListOrigin lists, ListSkin skin,
                                  cudaGraphConditionalHandle rebuild) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  bool moved_far = false;
  if (s < n) {
    const std::uint32_t i = order.sorted_id[s];
    place_in_cell_order(s, i, order.position, order.velocity, order.body, order.sorted_position, order.sorted_velocity);
    moved_far = moved_past_trigger(xyz(order.position[i]), xyz(lists.origin[s]), skin);
  }
  __shared__ bool last;
  if (__syncthreads_or(moved_far) && threadIdx.x == 0) atomicOr(&lists.refresh->moved_far, 1u);
  if (threadIdx.x == 0) {
    __threadfence();  // the flag is visible before the block counts as done
    last = atomicAdd(&lists.refresh->blocks_done, 1u) + 1u == gridDim.x;
  }
  __syncthreads();
  if (!last || threadIdx.x != 0) return;
  __threadfence();
  const bool any_moved_far = atomicExch(&lists.refresh->moved_far, 0u) != 0;
  cudaGraphSetConditional(rebuild, any_moved_far || lists.refresh->requested != 0 ? 1u : 0u);
  lists.refresh->blocks_done = 0;  // ready for the next step
  lists.refresh->recorded = 0;     // until the rebuild, if any, says otherwise
}

CellOrder cell_order(DeviceState& state) {
  return {state.keys.data(),      state.cell_start.data(),      state.unordered_id.data(),
          state.position.data(),  state.velocity.data(),        state.body.data(),
          state.sorted_id.data(), state.sorted_position.data(), state.sorted_velocity.data()};
}

ListOrigin list_origin(DeviceState& state) { return {state.list_origin.data(), state.list_refresh.data()}; }

}  // namespace

std::size_t scan_temp_bytes(std::uint32_t cells) {
  std::size_t bytes = 0;
  cuda_check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, static_cast<const std::uint32_t*>(nullptr),
                                           static_cast<std::uint32_t*>(nullptr), cells + 1),
             "size the cell-table scan");
  return bytes;
}

// Counts per cell, their scan (the cell table), slots, each particle's rank in its cell and its
// cell-ordered copy (see cell_count_kernel).
void launch_neighbour_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  const std::uint32_t cells = grid.cell_count();
  cell_count_kernel<<<blocks_for(n), kBlock, 0, stream>>>(state.position.data(), n, grid, state.keys.data(),
                                                         state.cell_count.data());
  std::size_t scan_bytes = state.scan_storage.size();
  cuda_check(cub::DeviceScan::ExclusiveSum(state.scan_storage.data(), scan_bytes, state.cell_count.data(),
                                           state.cell_start.data(), cells + 1, stream),
             "cell-table scan");
  cell_slot_kernel<<<blocks_for(n), kBlock, 0, stream>>>(state.keys.data(), n, state.cell_start.data(),
                                                        state.cell_count.data(), state.unordered_id.data());
  cell_rank_kernel<<<blocks_for(n), kBlock, 0, stream>>>(n, cell_order(state), list_origin(state));
}

void launch_list_check(DeviceState& state, const ListSkin& skin, cudaGraphConditionalHandle rebuild,
                       cudaStream_t stream) {
  const auto n = static_cast<std::uint32_t>(state.position.size());
  list_check_kernel<<<blocks_for(n), kBlock, 0, stream>>>(n, cell_order(state), list_origin(state), skin, rebuild);
}

}  // namespace mssph::kernels
