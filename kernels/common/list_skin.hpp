#pragma once
// The skin of the neighbour lists, the cpu backend's and the GPU teams': Verlet's neighbour list
// (Verlet 1967; Allen and Tildesley, "Computer Simulation of Liquids", its neighbour-list
// section). At a rebuild each list records every candidate within h + skin of its particle. Two
// particles within h now, each having moved at most half the skin since, were within h + skin then
// (triangle inequality), so they are listed: the lists, the cell order and the grid stay valid, and
// a step reads the lists instead of sorting the particles and walking the cells, until some
// particle has moved farther than half the skin (moved_past_trigger). The sums then take the same
// terms as over a fresh grid, in the order of the rebuild's walk.
//
// The grid's cells are h + skin wide (list_cell_size), so a rebuild's walk of 27 cells sees every
// candidate within h + skin.
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

// Skin width over h. A wider skin means rarer rebuilds but longer lists, which every step reads:
// (1 + skin/h)^3 as many entries as neighbours. results/decisions/ has the measurements.
inline constexpr float kSkinOverSupport = 0.1f;

// The trigger sits 1 % of the skin inside half of it, so the float rounding of the two distance
// tests (~1e-7 of the coordinates) cannot let a pair within h escape the lists.
inline constexpr float kTriggerOverHalfSkin = 0.99f;

struct ListSkin {
  float record_radius2;  // (h + skin)^2: a rebuild lists the candidates closer than this [m^2]
  float trigger2;        // a particle farther than this from its place at the rebuild forces the next one [m^2]
};

MSSPH_HD ListSkin list_skin(float h) {
  const float skin = kSkinOverSupport * h;
  const float trigger = kTriggerOverHalfSkin * 0.5f * skin;
  return {(h + skin) * (h + skin), trigger * trigger};
}

// Side of the grid's cells when the lists have a skin [m].
inline double list_cell_size(double h) { return (1.0 + kSkinOverSupport) * h; }

// Whether a particle now at `now`, at `recorded` when the lists were recorded, forces a rebuild.
MSSPH_HD bool moved_past_trigger(Vec3 now, Vec3 recorded, const ListSkin& skin) {
  return squared_norm(now - recorded) > skin.trigger2;
}

// What the GPU's steps share about the lists, in device memory: whether to rebuild, and whether
// this step did. Kept between steps, so the decision never goes through the host.
struct ListRefreshState {
  std::uint32_t requested;  // the next step must rebuild: the state was set from the host, or a list overflowed
  std::uint32_t moved_far;  // this step: some particle moved past the trigger
  std::uint32_t recorded;   // this step rebuilt the grid: its density pass records the lists
  std::uint32_t rebuilds;   // grid rebuilds since the state was created (counted by the rebuild)
};

}  // namespace mssph::kernels
