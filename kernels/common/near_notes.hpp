#pragma once
// What a one-lane density walk of a fluid particle leaves for the force walk of the same step: for
// each of the walk's first `capacity` segments (CellRanges::for_each_segment), the bit mask of the
// candidates within h. Both passes walk the same candidates (one lane: halves trimmed, no rows
// left out for a fluid particle) at the same positions, so the force walk takes those masks instead
// of testing ~180 candidates again, and tests only the segments past the notes
// (CellRanges::for_each_candidate_near): the same neighbours in the same order, the same bits.
//
// Ten 4-byte words a particle, in memory that holds nothing between the grid's copy into cell order
// and the force pass's store in a step (kernels/cuda's step_near_notes says which): a separate array
// would take the 1M fluid block from 117 to 157 bytes per particle, past the 130 its memory target
// allows. The words hold masks as float bits, the arrays' own type.
#include "particle_views.hpp"

#include <cstdint>

namespace mssph::kernels {

struct NearNotes {
  // A walk's 9 rows make 9 segments unless a row holds more than 32 candidates (near the walls'
  // denser layers) or wraps around the grid's period.
  static constexpr std::uint32_t capacity = 10;

  // Notes 0-7: four words a particle at its canonical index in each of two arrays of 16-byte
  // records; notes 8 and 9: one word a particle at its sorted index. All null: no notes taken.
  Vec4* canonical_first = nullptr;
  Vec4* canonical_second = nullptr;
  float* sorted_eighth = nullptr;
  float* sorted_ninth = nullptr;

  MSSPH_HD bool taken() const { return canonical_first != nullptr; }

  // Note k (below capacity) of the particle of canonical index i and sorted index s.
  MSSPH_HD float& word(std::uint32_t i, std::uint32_t s, std::uint32_t k) const {
    if (k < 8) return reinterpret_cast<float*>((k < 4 ? canonical_first : canonical_second) + i)[k % 4];
    return (k == 8 ? sorted_eighth : sorted_ninth)[s];
  }
  MSSPH_HD void put(std::uint32_t i, std::uint32_t s, std::uint32_t k, std::uint32_t near) const {
    if (k < capacity) word(i, s, k) = index_as_float_bits(near);
  }
  MSSPH_HD std::uint32_t get(std::uint32_t i, std::uint32_t s, std::uint32_t k) const {
    return index_from_float_bits(word(i, s, k));
  }
};

}  // namespace mssph::kernels
