#pragma once
// The shared-memory columns in which a thread of the force kernel holds its neighbours
// (common/held_neighbours.hpp).
#include "../common/held_neighbours.hpp"
#include "thread_blocks.cuh"

namespace mssph::kernels {

// This thread's column of its block's buffer of Capacity neighbours per thread. Column-major (entry
// k at [k * kBlock]), so the threads of a warp hold their k-th neighbour in consecutive words and
// write and read distinct banks whatever their counts. A thread runs one walk at a time.
template <unsigned Capacity>
__device__ HeldColumn held_column() {
  __shared__ std::uint32_t held[Capacity * kBlock];
  return {held + threadIdx.x, kBlock, Capacity};
}

}  // namespace mssph::kernels
