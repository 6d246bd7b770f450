#pragma once
// The launch shape of the `cuda` backend's one-thread-per-item kernels.
#include <cstddef>

namespace mssph::kernels {

// Threads per block; also the block size of the CUB block reductions, which must match it.
inline constexpr int kBlock = 256;

inline unsigned blocks_for(std::size_t n) { return static_cast<unsigned>((n + kBlock - 1) / kBlock); }

}  // namespace mssph::kernels
