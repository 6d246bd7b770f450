#pragma once
// The no-penetration condition of boundary bodies after step 4's leap-frog, float32
// (model/wall_exclusion.hpp says why and with what distance; reference twin:
// reference::keep_out_of_walls).
//
// Particle i moved from `previous` to `moved`. The move is rejected iff SOME boundary particle
// ends within step.wall_exclusion_distance of it while coming closer (boundary_approach): a
// condition on each candidate alone, so whether a move is rejected does not depend on the order
// in which the candidates are visited, and a team of GPU lanes can split the test
// (touches_wall over each lane's share, the shares' results ORed). Only what a rejection does to
// the velocity depends on the order, so that part (keep_out_of_walls) runs in one lane, and only
// for a rejected move. Boundary particles never move, so their sorted positions (from the start
// of the step) are where they are now, and the grid's 27 cells around the new position hold every
// boundary particle within h of it, a grid kept from an earlier step's rebuild too (list_skin.hpp).
#include "particle_views.hpp"

#include <cmath>

namespace mssph::kernels {

// What candidate t of the 27 cells around `moved` means for the move from `previous`.
struct BoundaryApproach {
  bool rejects_move;  // t is a boundary particle, r_new < d_wall and r_new < r_old
  Vec3 away;          // previous - x_b [m]
  float r2_old;       // |previous - x_b|^2 [m^2]
};

MSSPH_HD BoundaryApproach boundary_approach(const SortedView& v, Vec3 previous, Vec3 moved, std::uint32_t t) {
  const Vec4 p_b = v.position[t];
  if (v.bodies[body_of(p_b)].kind != kBoundary) return {false, {0, 0, 0}, 0.0f};
  const float limit2 = v.step.wall_exclusion_distance * v.step.wall_exclusion_distance;
  const Vec3 x_b = xyz(p_b);
  const float r2_new = squared_norm(moved - x_b);
  const Vec3 away = previous - x_b;
  const float r2_old = squared_norm(away);
  // "Not clear of it": a NaN distance (a blown-up particle) fails both comparisons and counts as
  // rejecting the move; the run's blow-up check stops such a run.
  const bool clear = r2_new >= limit2 || r2_new >= r2_old;
  return {!clear, away, r2_old};
}

// Relative margin of surely_clear_of_walls over d_wall. Its distances and boundary_approach's are
// rounded to a few float ulps (~1e-7 of the distances themselves: differences of coordinates are
// rounded relative to the difference), so 1e-3 leaves every such rounding far inside it.
inline constexpr float kWallClearanceMargin = 1e-3f;

// Whether a move of length sqrt(move2) surely ends farther than d_wall from every boundary
// particle when the nearest one was sqrt(nearest2) away at its start: each then ends at least
// sqrt(nearest2) - sqrt(move2) away (triangle inequality), so boundary_approach rejects nothing
// and the wall check can be skipped with the same outcome. +infinity (no boundary particle
// within h) is clear; a NaN (a blown-up particle) is not.
MSSPH_HD bool surely_clear_of_walls(float nearest2, float move2, float d_wall) {
  return std::sqrt(nearest2) - std::sqrt(move2) >= (1.0f + kWallClearanceMargin) * d_wall;
}

// Whether one of the candidates that candidates(visit) hands to visit is a boundary particle that
// rejects the move.
template <class Candidates>
MSSPH_HD bool touches_wall_among(const SortedView& v, Vec3 previous, Vec3 moved, Candidates&& candidates) {
  bool touches = false;
  candidates([&](std::uint32_t t) { touches = touches || boundary_approach(v, previous, moved, t).rejects_move; });
  return touches;
}

// Whether lane `lane` of a team of `lanes` finds, among its share of the candidates
// (CellRanges::for_each_candidate), a boundary particle that rejects the move. The move is
// rejected iff some lane of the team finds one; one lane alone (lanes = 1) tests every candidate.
MSSPH_HD bool touches_wall(const SortedView& v, Vec3 previous, Vec3 moved, std::uint32_t lane, std::uint32_t lanes) {
  return touches_wall_among(v, previous, moved,
                            [&](auto&& visit) { v.grid.for_each_candidate(moved, lane, lanes, visit); });
}

// Applies the rejection of the move from `previous` to `position` (with `velocity`): if some
// boundary particle rejects it, the particle returns to `previous` and loses its velocity
// component towards each such boundary particle, in the candidates' order. Returns whether the
// move was rejected: exactly when touches_wall is true for some lane of a team of any size.
MSSPH_HD bool keep_out_of_walls(const SortedView& v, Vec3 previous, Vec4& position, Vec4& velocity) {
  const Vec3 moved = xyz(position);
  Vec3 u = xyz(velocity);
  bool rejected = false;
  v.grid.for_each_candidate(moved, [&](std::uint32_t t) {
    const BoundaryApproach b = boundary_approach(v, previous, moved, t);
    if (!b.rejects_move) return;
    rejected = true;
    const Vec3 n = b.away * (1.0f / std::sqrt(b.r2_old));  // r_old > r_new >= 0
    const float approach = dot(u, n);
    if (approach < 0.0f) u = u - approach * n;
  });
  if (!rejected) return false;
  position = make_vec4(previous, 0.0f);
  velocity = make_vec4(u, 0.0f);
  return true;
}

}  // namespace mssph::kernels
