#pragma once
// The skin of the neighbour lists, the cpu backend's and the GPU teams': Verlet's neighbour list
// (Verlet 1967; Allen and Tildesley, "Computer Simulation of Liquids", its neighbour-list
// section). At a rebuild each list records every candidate within h + skin of its particle. Two
// particles within h now, having closed in by less than the skin since, were within h + skin then
// (triangle inequality), so they are listed: the lists, the cell order and the grid stay valid, and
// a step reads the lists instead of sorting the particles and walking the cells, until some
// particle has moved past its body's trigger (list_triggers2, moved_past_trigger). The sums then
// take the same terms as over a fresh grid, in the order of the rebuild's walk.
//
// The grid's cells are h + skin wide (list_cell_size), so a rebuild's walk of 27 cells sees every
// candidate within h + skin.
#include "fluid_physics.hpp"
#include "vec_math.hpp"

#include <cstdint>
#include <vector>

namespace mssph::kernels {

// Skin width over h. A wider skin means rarer rebuilds but longer lists, which every step reads:
// (1 + skin/h)^3 as many entries as neighbours. results/decisions/ has the measurements.
inline constexpr float kSkinOverSupport = 0.1f;

// How far two listed particles may close in before the next step rebuilds: 1 % of the skin inside
// it, so that the float rounding of the distance tests (~1e-7 of the coordinates) cannot let a pair
// within h escape the lists.
inline constexpr float kClosingOverSkin = 0.99f;

struct ListSkin {
  float record_radius2;  // (h + skin)^2: a rebuild lists the candidates closer than this [m^2]
  float closing;         // how far two listed particles may close in between rebuilds [m]
};

MSSPH_HD ListSkin list_skin(float h) {
  const float skin = kSkinOverSupport * h;
  return {(h + skin) * (h + skin), kClosingOverSkin * skin};
}

// Side of the grid's cells when the lists have a skin [m].
inline double list_cell_size(double h) { return (1.0 + kSkinOverSupport) * h; }

// Each body's trigger, squared [m^2]: how far its particles may move from where the lists were
// recorded. Particles of bodies b and c close in by at most t_b + t_c, which must stay within the
// closing: half of it each, in general. Boundaries and fixed rigid bodies do not move, and a rigid
// or deformable body never lists its own particles (body_left_out): where the only body that moves
// is such a body (a tool over a resting scene), it may travel the whole closing before a rebuild,
// and a resting body not at all.
inline std::vector<float> list_triggers2(const std::vector<BodyParameters>& bodies, const ListSkin& skin) {
  const auto moves = [](const BodyParameters& b) {
    return b.kind != kBoundary && (b.kind != kRigid || b.rigid_index != kNotRigid);
  };
  std::size_t moving = 0, moving_listing_itself = 0;
  for (const BodyParameters& b : bodies) {
    moving += moves(b) ? 1 : 0;
    moving_listing_itself += moves(b) && !takes_own_body_at_rest(b) ? 1 : 0;
  }
  const bool one_tool = moving == 1 && moving_listing_itself == 0;
  std::vector<float> triggers2;
  for (const BodyParameters& b : bodies) {
    const float trigger = one_tool ? (moves(b) ? skin.closing : 0.0f) : 0.5f * skin.closing;
    triggers2.push_back(trigger * trigger);
  }
  return triggers2;
}

// Whether a particle now at `now`, at `recorded` when the lists were recorded, forces a rebuild:
// `trigger2`, its body's (list_triggers2).
MSSPH_HD bool moved_past_trigger(Vec3 now, Vec3 recorded, float trigger2) {
  return squared_norm(now - recorded) > trigger2;
}

// What the GPU's steps share about the lists, in device memory: whether to rebuild, and whether
// this step did. Kept between steps, so the decision never goes through the host.
struct ListRefreshState {
  std::uint32_t requested;  // the next step must rebuild: the state was set from the host, or a list overflowed
  std::uint32_t moved_far;  // the next step must rebuild: the last step moved a particle past its body's trigger
  std::uint32_t recorded;   // this step rebuilt the grid: its density pass records the lists
  std::uint32_t rebuilds;   // grid rebuilds since the state was created (counted by the rebuild)
};

}  // namespace mssph::kernels
