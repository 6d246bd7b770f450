#pragma once
// How many lanes of a warp share each particle's neighbour sums on the GPU, and with that whether
// the sums keep neighbour lists (list_skin.hpp): teams of 2 or more lanes keep them, one lane walks
// the grid every step. Plain arithmetic on counts, so the host tests it without a device.
#include <cstddef>

namespace mssph::kernels {

// The most lanes (up to 8) that keep particles * lanes within `threads`.
inline unsigned most_lanes_within(std::size_t particles, std::size_t threads) {
  unsigned lanes = 8;
  while (lanes > 1 && particles * lanes > threads) lanes /= 2;
  return lanes;
}

// Lanes per particle of the density and force sums. By size: as many lanes (up to 8) as keep the
// teams within one wave of the threads the GPU holds, so a small scene has ~8x the threads in
// flight; between one and four waves, teams of 2 lanes, whose lists (list_skin.hpp) skip grid walks
// that pay for the second lane; beyond, one lane per particle, which wastes no shuffles and keeps
// no lists (device_arrays.hpp, team_list_capacity: a million-particle fluid stays within its memory
// budget). `lists_always` (the scene's simulation/neighbour_lists: always) keeps teams of at least
// 2 lanes, and so lists, at any size: they take ~470 more bytes a particle and pay where most
// particles' lists are short or their walks cost more than a list, as a rigid or deformable
// particle's, whose own body is never listed (results/decisions/068).
inline unsigned choose_team_lanes(std::size_t particles, std::size_t resident_threads, bool lists_always) {
  const unsigned lanes = most_lanes_within(particles, resident_threads);
  if (lanes > 1) return lanes;
  return lists_always || particles * 2 <= 4 * resident_threads ? 2 : 1;
}

// Lanes per deformable particle of the bond sums: the bond passes' ~60 registers let half as many
// threads reside as the GPU could hold, and since their teams hand the serial rest of step 1 to one
// thread per particle, more lanes pay only while they fit one wave of those.
inline unsigned choose_bond_team_lanes(std::size_t deformables, std::size_t resident_threads) {
  return most_lanes_within(deformables, resident_threads / 2);
}

}  // namespace mssph::kernels
