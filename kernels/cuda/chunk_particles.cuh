#pragma once
// How a block walks its chunk (chunk_tables.hpp): thread t takes the chunk's particles t,
// t + kBlock, t + 2 kBlock, ... in that order, which fixes the order of every per-thread sum.
#include "chunk_tables.hpp"
#include "thread_blocks.cuh"

#include <cstdint>

namespace mssph::kernels {

static_assert(kChunk % kBlock == 0, "a chunk is a whole number of strides");

// Calls visit(i) for this thread's particles of the chunk [first, first + count), count <= kChunk,
// in order; the block has kBlock threads. In a full chunk (all but a body's last) the
// kChunk / kBlock trips are unrolled without a bound test, a shorter chunk (a body's last, or a
// rigid body's, rigid_chunk_size) as far with one, so the compiler can issue a thread's loads
// together instead of one round trip to memory after another: with one block per chunk a small
// body has few blocks, and those round trips would be the whole cost. A visit that stores to global
// memory keeps its loads from moving ahead (the results do not depend on it, only the speed).
template <class Visit>
__device__ void for_each_chunk_particle(std::uint32_t first, std::uint32_t count, Visit&& visit) {
  if (count == kChunk) {
#pragma unroll
    for (std::uint32_t k = 0; k < kChunk / kBlock; ++k) visit(first + threadIdx.x + k * kBlock);
  } else {
#pragma unroll(kChunk / kBlock)
    for (std::uint32_t offset = threadIdx.x; offset < count; offset += kBlock) visit(first + offset);
  }
}

}  // namespace mssph::kernels
