// The deformable passes' per-particle matrices (kernels/common/mat3_store.hpp): the cpu backend's
// records and the cuda backend's planes must each put entry k of matrix d where their layout says,
// and load what store wrote.
#include "common/mat3_store.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using mssph::kernels::Mat3;
using mssph::kernels::Mat3Planes;
using mssph::kernels::Mat3Records;

constexpr std::uint32_t kCount = 5;

float entry_value(std::uint32_t d, int k) { return static_cast<float>(10 * d + static_cast<std::uint32_t>(k)); }

// Stores every matrix with its own entries, then checks each stored entry (entry(d, k) reads it
// where the layout puts it) and each loaded matrix. Every slot is written once: a wrong index puts
// some value where another belongs, or leaves the -1 the slots were filled with.
template <class Store, class Entry>
void expect_layout(const Store& store, Entry entry) {
  for (std::uint32_t d = 0; d < kCount; ++d) {
    Mat3 m;
    for (int k = 0; k < 9; ++k) m.m[k] = entry_value(d, k);
    store.store(d, m);
  }
  for (std::uint32_t d = 0; d < kCount; ++d) {
    const Mat3 loaded = store.load(d);
    for (int k = 0; k < 9; ++k) {
      EXPECT_EQ(entry(d, k), entry_value(d, k)) << "matrix " << d << ", entry " << k;
      EXPECT_EQ(loaded.m[k], entry_value(d, k)) << "matrix " << d << ", entry " << k;
    }
  }
}

TEST(Mat3Store, RecordsHoldEachMatrixTogether) {
  std::vector<Mat3> matrices(kCount);
  for (Mat3& m : matrices) {
    for (float& e : m.m) e = -1.0f;
  }
  expect_layout(Mat3Records{matrices.data()}, [&](std::uint32_t d, int k) { return matrices[d].m[k]; });
}

TEST(Mat3Store, PlanesHoldEntryKOfEveryMatrixTogether) {
  std::vector<float> entries(9 * kCount, -1.0f);
  expect_layout(Mat3Planes{entries.data(), kCount},
                [&](std::uint32_t d, int k) { return entries[std::size_t(k) * kCount + d]; });
}

}  // namespace
