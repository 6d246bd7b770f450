#pragma once
// The launch shape of the `cuda` backend's one-thread-per-item kernels.
#include <cstddef>

namespace mssph::kernels {

// Threads per block; also the block size of the CUB block reductions, which must match it.
inline constexpr int kBlock = 256;

// Blocks of `block` threads that cover n items.
inline unsigned blocks_for(std::size_t n, unsigned block = kBlock) {
  return static_cast<unsigned>((n + block - 1) / block);
}

}  // namespace mssph::kernels
