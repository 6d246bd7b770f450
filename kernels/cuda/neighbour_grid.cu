#include "neighbour_grid.cuh"

#include "../common/block_share.hpp"
#include "../common/fluid_physics.hpp"
#include "../common/list_skin.hpp"
#include "cuda_check.hpp"
#include "dependent_launch.cuh"
#include "thread_blocks.cuh"

#include <cooperative_groups.h>
#include <cub/cub.cuh>

#include <algorithm>

namespace mssph::kernels {
namespace {

namespace cg = cooperative_groups;

// What the grid kernel reads and writes. The list fields are null without the teams' lists.
struct GridArrays {
  GridShape grid;
  std::uint32_t n;
  const Vec4* position;
  const Vec4* velocity;
  const std::uint32_t* body;
  std::uint32_t* keys;  // half keys (GridShape::half_key_of)
  std::uint32_t* cell_count;
  std::uint32_t* cell_start;
  std::uint32_t* cell_middle;
  std::uint16_t* cell_body;     // null where no walk leaves rows out (CellRanges)
  std::uint32_t* unordered_id;  // half ids (half_id)
  std::uint32_t* block_total;   // one per block of the kernel (scan_cell_counts)
  std::uint32_t* sorted_id;
  std::uint32_t* place_of;  // null without lists or without rigid bodies (next_cell_order.cuh)
  Vec4* sorted_position;
  Vec4* sorted_velocity;
  Vec4* list_origin;          // canonical: where each particle stood at the last rebuild
  ListRefreshState* refresh;  // whether to rebuild, and whether this step did

  // Copies the particle of place s in cell order (sorted_id) there.
  __device__ void copy_into_cell_order(std::uint32_t s) const {
    place_in_cell_order(s, sorted_id[s], position, velocity, body, sorted_position, sorted_velocity);
  }

  // The grid's last stage (grid_kernel): copies the particle of place s in cell order there and,
  // where cells note their body, takes the second stage of CellRanges::cell_body (entry_joined_by)
  // once each cell's first particle has written its sole_body_entry: the particle marks its cell
  // mixed where its body differs. All such writes store kMixedCell, so their order does not
  // matter. Every load comes before the stores, for the reason place_in_cell_order gives.
  __device__ void copy_into_cell_order_and_join(std::uint32_t s) const {
    if (!cell_body) return copy_into_cell_order(s);
    const CellOrderedParticle particle = cell_ordered_particle(sorted_id[s], position, velocity, body);
    const std::uint32_t cell = grid.key_of(xyz(particle.position));
    const std::uint16_t entry = cell_body[cell];
    sorted_position[s] = particle.position;
    sorted_velocity[s] = particle.velocity;
    if (entry_joined_by(entry, body_of(particle.position)) != entry) cell_body[cell] = kMixedCell;
  }
};

// A particle's half id: its index, plus 2^31 in its cell's upper half, so that half ids order a
// cell's particles as the grid sorts them, its lower half first. Indices take at most 31 bits
// (GridShape::half_key_of says why).
constexpr std::uint32_t kUpperHalfBit = 1u << 31;
__device__ std::uint32_t half_id(std::uint32_t i, std::uint32_t half_key) {
  return half_key & 1u ? i | kUpperHalfBit : i;
}

// Visits items first, first + stride, ... below count: every thread of the kernel's grid, which
// is no larger than the blocks that fit on the device at once (a cooperative launch).
template <class Visit>
__device__ void for_each_grid_item(std::uint32_t count, Visit&& visit) {
  const std::uint32_t stride = gridDim.x * blockDim.x;
  for (std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x; k < count; k += stride) visit(k);
}

// Stage 2 below: cell_start, the exclusive scan of the cells' counts, and cell_middle, where each
// cell's upper half begins. Each block owns a share of the table (block_share): it adds up its
// share's counts, then, once every block has, the totals of the blocks before it, and scans its
// share from there a tile at a time (cub::BlockScan).
__device__ void scan_cell_counts(const GridArrays& a, cg::grid_group grid) {
  using Reduce = cub::BlockReduce<std::uint32_t, kBlock>;
  using Scan = cub::BlockScan<std::uint32_t, kBlock>;
  __shared__ union {
    typename Reduce::TempStorage reduce;
    typename Scan::TempStorage scan;
  } storage;
  __shared__ std::uint32_t share_offset;
  const auto [first, end] = block_share(a.grid.cell_count() + 1, gridDim.x, blockIdx.x);
  std::uint32_t in_share = 0;
  for (std::uint32_t k = first + threadIdx.x; k < end; k += blockDim.x) in_share += a.cell_count[k];
  in_share = Reduce(storage.reduce).Sum(in_share);
  if (threadIdx.x == 0) a.block_total[blockIdx.x] = in_share;
  grid.sync();
  std::uint32_t before = 0;
  for (std::uint32_t b = threadIdx.x; b < blockIdx.x; b += blockDim.x) before += a.block_total[b];
  before = Reduce(storage.reduce).Sum(before);
  if (threadIdx.x == 0) share_offset = before;
  __syncthreads();
  std::uint32_t running = share_offset;
  for (std::uint32_t tile = first; tile < end; tile += blockDim.x) {
    const std::uint32_t k = tile + threadIdx.x;
    std::uint32_t below = 0;
    std::uint32_t tile_total = 0;
    Scan(storage.scan).ExclusiveSum(k < end ? a.cell_count[k] : 0u, below, tile_total);
    if (k < end) {
      a.cell_start[k] = running + below;
      a.cell_middle[k] = running + below;  // an empty cell's; stage 4 writes the others'
    }
    running += tile_total;
    __syncthreads();  // the next tile reuses the scan's storage
  }
}

// With lists, whether this step must rebuild the grid, the same in every thread: the last step
// moved a particle past its body's trigger (list_check.cuh), or a rebuild was requested.
__device__ bool lists_expired(const GridArrays& a) { return a.refresh->moved_far != 0 || a.refresh->requested != 0; }

// The neighbour grid by a counting sort, stable like a sort of (half key, index) pairs, so every
// run lays the particles out alike: by cell as on the host, and within a cell its lower half along
// x first (CellRanges::cell_middle). One cooperative kernel whose stages wait for each other at
// grid-wide barriers:
// 1. each particle's half key, and a count per cell (integer atomics: the counts, not their
//    order, are kept);
// 2. the cell table, cell_start[k] = particles in cells below k (scan_cell_counts);
// 3. each particle takes a slot in its cell's range (atomically, in no fixed order), writes its
//    half id there and gives back its count, so the counts are zero again for the next rebuild;
// 4. each particle counts the half ids of its cell smaller than its own in those slots: its rank
//    in the cell's sorted order, so its place in cell order (sorted_id); the first of each cell
//    also notes where its upper half begins (CellRanges::cell_middle) and its body
//    (CellRanges::cell_body);
// 5. each place in cell order copies its particle there: the writes in order, the reads gathered
//    (each particle copying itself to its place would scatter the writes, and a lattice's
//    particle and its next along x, whose 16-byte entries share a 32-byte sector, land in the two
//    halves of their cell); a particle whose body is not its cell's first's marks the cell mixed.
// With lists (`check`), while they hold (lists_expired), the kernel only marks the step as one
// whose density pass visits the lists: the step before wrote the particles in the last rebuild's
// cell order where it moved them (next_cell_order.cuh). One launch per step, with no grid-wide
// barrier, separate check kernel or conditional graph node. A rebuild with lists also records
// where each particle stands and its place in cell order, marks the step as one whose density pass
// records the lists, and takes back what caused it.
__global__ void __launch_bounds__(kBlock) grid_kernel(GridArrays a, bool check) {
  follow_previous_kernel();
  const cg::grid_group grid = cg::this_grid();
  if (check && !lists_expired(a)) {
    if (grid.thread_rank() == 0) a.refresh->recorded = 0;
    return;
  }
  for_each_grid_item(a.n, [&](std::uint32_t i) {
    const Vec4 p = a.position[i];
    const std::uint32_t key = a.grid.half_key_of(xyz(p));
    a.keys[i] = key;
    atomicAdd(&a.cell_count[key >> 1], 1u);
    if (a.list_origin) a.list_origin[i] = p;
  });
  grid.sync();
  scan_cell_counts(a, grid);
  grid.sync();
  for_each_grid_item(a.n, [&](std::uint32_t i) {
    const std::uint32_t key = a.keys[i];
    const std::uint32_t cell = key >> 1;
    a.unordered_id[a.cell_start[cell] + atomicSub(&a.cell_count[cell], 1u) - 1u] = half_id(i, key);
  });
  grid.sync();
  if (a.refresh && grid.thread_rank() == 0) {
    *a.refresh = {/*requested=*/0, /*moved_far=*/0, /*recorded=*/1, a.refresh->rebuilds + 1};
  }
  for_each_grid_item(a.n, [&](std::uint32_t i) {
    const std::uint32_t key = a.keys[i];
    const std::uint32_t cell = key >> 1;
    const std::uint32_t own = half_id(i, key);
    const std::uint32_t first = a.cell_start[cell];
    const std::uint32_t end = a.cell_start[cell + 1];
    std::uint32_t rank = 0, lower_half = 0;
#pragma unroll 4  // the slots' loads in flight together
    for (std::uint32_t slot = first; slot < end; ++slot) {
      const std::uint32_t other = a.unordered_id[slot];
      rank += other < own ? 1u : 0u;
      lower_half += other < kUpperHalfBit ? 1u : 0u;
    }
    if (rank == 0) {
      a.cell_middle[cell] = first + lower_half;
      if (a.cell_body) a.cell_body[cell] = sole_body_entry(a.body[i]);
    }
    a.sorted_id[first + rank] = i;
    if (a.place_of) a.place_of[i] = first + rank;
  });
  grid.sync();
  for_each_grid_item(a.n, [&](std::uint32_t s) { a.copy_into_cell_order_and_join(s); });
}

// Copies every particle into the last rebuild's cell order: the host replaced the canonical state
// and kept the cells.
__global__ void __launch_bounds__(kBlock) cell_order_copy_kernel(GridArrays a) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < a.n) a.copy_into_cell_order(s);
}

GridArrays grid_arrays(DeviceState& state, const GridShape& grid) {
  return {grid,
          static_cast<std::uint32_t>(state.position.size()),
          state.position.data(),
          state.velocity.data(),
          state.body.data(),
          state.keys.data(),
          state.cell_count.data(),
          state.cell_start.data(),
          state.cell_middle.data(),
          state.cell_body.data(),
          state.unordered_id.data(),
          state.block_total.data(),
          state.sorted_id.data(),
          state.place_of.data(),
          state.sorted_position.data(),
          state.sorted_velocity.data(),
          state.list_origin.data(),
          state.list_refresh.data()};
}

void launch_grid_kernel(DeviceState& state, const GridShape& grid, bool check, cudaStream_t stream) {
  GridArrays a = grid_arrays(state, grid);
  // One block per entry of block_total, which was sized by grid_kernel_blocks for this device.
  const auto blocks = static_cast<unsigned>(state.block_total.size());
  void* arguments[] = {&a, &check};
  cuda_check(cudaLaunchCooperativeKernel(reinterpret_cast<const void*>(&grid_kernel), dim3(blocks), dim3(kBlock),
                                         arguments, 0, stream),
             "launch the neighbour grid");
}

}  // namespace

// As many blocks as the items need, at most as many as fit on the device at once.
unsigned grid_kernel_blocks(std::size_t particles, std::uint32_t cells) {
  int device = 0;
  int multiprocessors = 0;
  int per_multiprocessor = 0;
  cuda_check(cudaGetDevice(&device), "get the device");
  cuda_check(cudaDeviceGetAttribute(&multiprocessors, cudaDevAttrMultiProcessorCount, device), "count multiprocessors");
  cuda_check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_multiprocessor, grid_kernel, kBlock, 0),
             "size the neighbour grid's cooperative launch");
  const unsigned resident = static_cast<unsigned>(multiprocessors * per_multiprocessor);
  return std::max(1u, std::min(resident, blocks_for(std::max<std::size_t>(particles, std::size_t{cells} + 1))));
}

void launch_neighbour_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream) {
  launch_grid_kernel(state, grid, false, stream);
}

void launch_list_step_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream) {
  launch_grid_kernel(state, grid, true, stream);
}

void launch_cell_order_copy(DeviceState& state, const GridShape& grid, cudaStream_t stream) {
  cell_order_copy_kernel<<<blocks_for(state.position.size()), kBlock, 0, stream>>>(grid_arrays(state, grid));
  cuda_check(cudaGetLastError(), "copy the particles into cell order");
}

}  // namespace mssph::kernels
