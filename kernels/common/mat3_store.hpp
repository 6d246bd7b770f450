#pragma once
// One Mat3 per deformable particle, laid out as the backend's loops read it; both layouts load and
// store matrix d alike, so the deformable passes (elastic_physics.hpp) are written once for both.
// - Mat3Records (the cpu backend's): each matrix's nine entries together. A host thread reads whole
//   matrices one at a time, and a record sits on one or two cache lines where planes take nine.
// - Mat3Planes (the cuda backend's): entry k of every matrix together, at k * count + d. A warp's
//   lanes serve consecutive particles whose k-th bonds mostly reach consecutive neighbours, so each
//   entry of the 32 matrices a warp gathers comes from one or two cache lines, where records would
//   spread it over nine.
#include "host_device.hpp"
#include "vec_math.hpp"

#include <cstddef>
#include <cstdint>

namespace mssph::kernels {

struct Mat3Records {
  Mat3* matrices;  // count matrices

  MSSPH_HD const Mat3& load(std::uint32_t d) const { return matrices[d]; }
  MSSPH_HD void store(std::uint32_t d, const Mat3& m) const { matrices[d] = m; }
};

struct Mat3Planes {
  float* entries;       // 9 * count floats
  std::uint32_t count;  // matrices

  MSSPH_HD Mat3 load(std::uint32_t d) const {
    Mat3 m;
    for (int k = 0; k < 9; ++k) m.m[k] = entries[std::size_t(k) * count + d];
    return m;
  }
  MSSPH_HD void store(std::uint32_t d, const Mat3& m) const {
    for (int k = 0; k < 9; ++k) entries[std::size_t(k) * count + d] = m.m[k];
  }
};

}  // namespace mssph::kernels
