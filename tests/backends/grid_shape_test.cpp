// choose_grid_shape (kernels/common/float_scene.cpp) puts the wrap of the grid's period along x
// beside the scene (GridShape::origin_x), so that no particle's row of three cells along x wraps
// and every row is one range of sorted particles (CellRanges::for_each_range). Checked on lattice
// blocks centred on the origin (as the benchmarks' blocks are), far from it on either side, and for
// two support radii, from each particle's own cells; and the check finds the wrapped rows of a block
// centred on the origin when the wrap is left at x = 0.
#include "common/float_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace mssph::testing {
namespace {

// A lattice block of 0.5 x 0.3 x 0.2 m, spacing h / 2, centred at `centre`.
std::vector<kernels::Vec4> lattice_block(kernels::Vec3 centre, double h) {
  const double spacing = h / 2.0;
  const double size[3] = {0.5, 0.3, 0.2};
  int count[3];
  for (int a = 0; a < 3; ++a) count[a] = static_cast<int>(std::lround(size[a] / spacing));
  std::vector<kernels::Vec4> block;
  for (int k = 0; k < count[2]; ++k) {
    for (int j = 0; j < count[1]; ++j) {
      for (int i = 0; i < count[0]; ++i) {
        const auto at = [&](int n, int a) { return static_cast<float>((n + 0.5) * spacing - 0.5 * size[a]); };
        block.push_back(kernels::Vec4{centre.x + at(i, 0), centre.y + at(j, 1), centre.z + at(k, 2), 0.0f});
      }
    }
  }
  return block;
}

// The rows of three cells along x, around each particle and its 8 neighbouring rows, whose keys
// are not consecutive: the rows a walk takes as three separate cells.
std::size_t wrapped_rows(const std::vector<kernels::Vec4>& particles, const kernels::GridShape& shape) {
  std::size_t wrapped = 0;
  for (const kernels::Vec4& p : particles) {
    int cx, cy, cz;
    shape.cell_of(kernels::xyz(p), cx, cy, cz);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        if (shape.key(cx + 1, cy + dy, cz + dz) != shape.key(cx - 1, cy + dy, cz + dz) + 2) ++wrapped;
      }
    }
  }
  return wrapped;
}

TEST(GridShape, NoParticlesRowOfCellsWrapsAlongX) {
  for (const double h : {0.02, 0.05}) {
    for (const kernels::Vec3 centre : {kernels::Vec3{0.0f, 0.0f, 0.1f}, kernels::Vec3{123.4567f, 10.0f, -3.0f},
                                       kernels::Vec3{-98.76f, -0.3f, 7.0f}}) {
      SCOPED_TRACE(::testing::Message() << "h " << h << ", centre x " << centre.x);
      const std::vector<kernels::Vec4> block = lattice_block(centre, h);
      const kernels::GridShape shape = kernels::choose_grid_shape(block, h);
      EXPECT_EQ(wrapped_rows(block, shape), 0u);
    }
  }
}

TEST(GridShape, ABlockCentredOnTheOriginWrapsThereWithoutTheShift) {
  const double h = 0.02;
  const std::vector<kernels::Vec4> block = lattice_block(kernels::Vec3{0.0f, 0.0f, 0.1f}, h);
  kernels::GridShape shape = kernels::choose_grid_shape(block, h);
  shape.origin_x = 0;
  // The particles of the two cell columns beside x = 0 (4 of the block's 50 particle columns),
  // each with its 9 rows.
  EXPECT_EQ(wrapped_rows(block, shape), 4u * 30u * 20u * 9u);
}

}  // namespace
}  // namespace mssph::testing
