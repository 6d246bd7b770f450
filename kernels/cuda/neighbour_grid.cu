#include "neighbour_grid.cuh"

#include "../common/fluid_physics.hpp"
#include "thread_blocks.cuh"

#include <cub/cub.cuh>

namespace mssph::kernels {
namespace {

// The neighbour grid by a counting sort, stable like a sort of (key, index) pairs (the cpu
// backend's order), so every run lays the particles out alike. Four kernels and a CUB scan:
// 1. each particle's cell key, and a count per cell (integer atomics: the counts, not their
//    order, are kept);
// 2. an exclusive scan of the counts: the cell table, cell_start[k] = particles in cells below k;
// 3. each particle takes a slot in its cell's range (atomically, in no fixed order) and gives
//    back its count, so the counts are zero again for the next step; then
// 4. one thread per cell sorts its few slots by particle index (insertion sort), which makes
//    the order within a cell canonical; then one thread per particle copies it into cell order.
__global__ void cell_count_kernel(const Vec4* position, std::uint32_t n, GridShape grid, std::uint32_t* keys,
                                  std::uint32_t* cell_count) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = grid.key_of(xyz(position[i]));
  keys[i] = key;
  atomicAdd(&cell_count[key], 1u);
}

__global__ void cell_slot_kernel(const std::uint32_t* keys, std::uint32_t n, const std::uint32_t* cell_start,
                                 std::uint32_t* cell_count, std::uint32_t* sorted_id) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = keys[i];
  sorted_id[cell_start[key] + atomicSub(&cell_count[key], 1u) - 1u] = i;
}

__global__ void cell_sort_kernel(std::uint32_t cells, const std::uint32_t* cell_start, std::uint32_t* sorted_id) {
  const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= cells) return;
  const std::uint32_t first = cell_start[k];
  const std::uint32_t end = cell_start[k + 1];
  for (std::uint32_t s = first + 1; s < end; ++s) {
    const std::uint32_t id = sorted_id[s];
    std::uint32_t t = s;
    for (; t > first && sorted_id[t - 1] > id; --t) sorted_id[t] = sorted_id[t - 1];
    sorted_id[t] = id;
  }
}

__global__ void cell_order_kernel(std::uint32_t n, const std::uint32_t* sorted_id, const Vec4* position,
                                  const Vec4* velocity, const std::uint32_t* body, Vec4* sorted_position,
                                  Vec4* sorted_velocity) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < n) place_in_cell_order(s, sorted_id, position, velocity, body, sorted_position, sorted_velocity);
}

}  // namespace

std::size_t scan_temp_bytes(std::uint32_t cells) {
  std::size_t bytes = 0;
  cuda_check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, static_cast<const std::uint32_t*>(nullptr),
                                           static_cast<std::uint32_t*>(nullptr), cells + 1),
             "size the cell-table scan");
  return bytes;
}

// Counts per cell, their scan (the cell table), slots, the order within each cell, cell-ordered
// copies (see cell_count_kernel).
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
                                                        state.cell_count.data(), state.sorted_id.data());
  cell_sort_kernel<<<blocks_for(cells), kBlock, 0, stream>>>(cells, state.cell_start.data(), state.sorted_id.data());
  cell_order_kernel<<<blocks_for(n), kBlock, 0, stream>>>(n, state.sorted_id.data(), state.position.data(),
                                                         state.velocity.data(), state.body.data(),
                                                         state.sorted_position.data(), state.sorted_velocity.data());
}

}  // namespace mssph::kernels
