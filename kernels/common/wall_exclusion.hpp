#pragma once
// The no-penetration condition of boundary bodies after step 4's leap-frog, float32
// (model/wall_exclusion.hpp says why and with what distance; reference twin:
// reference::keep_out_of_walls).
#include "particle_views.hpp"

namespace mssph::kernels {

// Particle i moved from `previous` to `position` with `velocity`. If the move brings it within
// step.wall_exclusion_distance of a boundary particle while coming closer to it, the move is
// rejected: the particle returns to `previous` and loses its velocity component towards each such
// boundary particle. Boundary particles never move, so their sorted positions (from the start of
// the step) are where they are now; the grid's 27 cells around the new position hold every
// particle within h of it.
MSSPH_HD void keep_out_of_walls(const SortedView& v, Vec3 previous, Vec4& position, Vec4& velocity) {
  const float limit2 = v.step.wall_exclusion_distance * v.step.wall_exclusion_distance;
  const Vec3 moved = xyz(position);
  Vec3 u = xyz(velocity);
  bool rejected = false;
  v.grid.for_each_candidate(moved, [&](std::uint32_t t) {
    const Vec4 p_b = v.position[t];
    if (v.bodies[body_of(p_b)].kind != kBoundary) return;
    const Vec3 x_b = xyz(p_b);
    const float r2_new = squared_norm(moved - x_b);
    const Vec3 away = previous - x_b;
    const float r2_old = squared_norm(away);
    if (r2_new >= limit2 || r2_new >= r2_old) return;
    rejected = true;
    const Vec3 n = away * (1.0f / std::sqrt(r2_old));  // r_old > r_new >= 0
    const float approach = dot(u, n);
    if (approach < 0.0f) u = u - approach * n;
  });
  if (!rejected) return;
  position = make_vec4(previous, 0.0f);
  velocity = make_vec4(u, 0.0f);
}

}  // namespace mssph::kernels
