#pragma once
// How a cooperative kernel (every block resident at once) splits a table among its blocks: block b
// of `blocks` owns one contiguous share, the shares in block order tile [0, items) without overlap,
// and blocks past the end get empty shares. The grid kernel scans the cell table this way
// (kernels/cuda/neighbour_grid.cu): a block adds up its share, then the shares before it.
#include "host_device.hpp"

#include <cstdint>

namespace mssph::kernels {

struct BlockShare {
  std::uint32_t first;
  std::uint32_t end;  // one past the last item
};

MSSPH_HD BlockShare block_share(std::uint32_t items, std::uint32_t blocks, std::uint32_t block) {
  const std::uint32_t per_block = (items + blocks - 1) / blocks;
  const std::uint32_t first = per_block * block < items ? per_block * block : items;
  const std::uint32_t end = items - first < per_block ? items : first + per_block;
  return {first, end};
}

}  // namespace mssph::kernels
