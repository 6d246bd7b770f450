// The grid kernel's scan splits the cell table among its blocks (kernels/common/block_share.hpp):
// a cell counted by two blocks, or by none, would shift every cell_start after it. The shares
// must tile the table in block order, whatever the table's size against the blocks.
#include "common/block_share.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace {

using mssph::kernels::block_share;
using mssph::kernels::BlockShare;

// Tables of 2^k + 1 entries (the grid's cells and the end), and sizes around the block count.
TEST(BlockShare, SharesTileTheTableInBlockOrder) {
  for (std::uint32_t blocks : {1u, 2u, 3u, 132u, 1056u}) {
    for (std::uint32_t items : {1u, 2u, 5u, 65u, 131u, 132u, 133u, 1055u, 1056u, 1057u, 4097u, (1u << 20) + 1u}) {
      std::uint32_t next = 0;
      std::uint32_t largest = 0;
      for (std::uint32_t b = 0; b < blocks; ++b) {
        const BlockShare share = block_share(items, blocks, b);
        ASSERT_EQ(share.first, next) << items << " items, " << blocks << " blocks, block " << b;
        ASSERT_LE(share.first, share.end) << items << " items, " << blocks << " blocks, block " << b;
        largest = share.end - share.first > largest ? share.end - share.first : largest;
        next = share.end;
      }
      EXPECT_EQ(next, items) << items << " items, " << blocks << " blocks";
      // Balanced: no share longer than the items spread evenly, rounded up.
      EXPECT_EQ(largest, (items + blocks - 1) / blocks) << items << " items, " << blocks << " blocks";
    }
  }
}

}  // namespace
