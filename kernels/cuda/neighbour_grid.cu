#include "neighbour_grid.cuh"

#include "../common/fluid_physics.hpp"
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

__global__ void cell_rank_kernel(std::uint32_t n, CellOrder order) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = order.keys[i];
  const std::uint32_t first = order.cell_start[key];
  const std::uint32_t end = order.cell_start[key + 1];
  std::uint32_t rank = 0;
  for (std::uint32_t slot = first; slot < end; ++slot) rank += order.unordered_id[slot] < i ? 1u : 0u;
  const std::uint32_t s = first + rank;
  order.sorted_id[s] = i;
  place_in_cell_order(s, i, order.position, order.velocity, order.body, order.sorted_position, order.sorted_velocity);
}

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
  const CellOrder order{state.keys.data(),      state.cell_start.data(),     state.unordered_id.data(),
                        state.position.data(),  state.velocity.data(),       state.body.data(),
                        state.sorted_id.data(), state.sorted_position.data(), state.sorted_velocity.data()};
  cell_rank_kernel<<<blocks_for(n), kBlock, 0, stream>>>(n, order);
}

}  // namespace mssph::kernels
