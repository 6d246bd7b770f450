#pragma once
// Which particles' force sums walk, and in what order the force pass takes them. A rigid or
// deformable particle's sums walk only with another body within h of it (may_feel_forces); in cell
// order those lie in the few cells along a contact, one or two to a warp, and a warp walks as long
// as its longest walk. The density pass, which finds each particle's nearest other body, records a
// byte a particle (ForceWalk) and, with one lane a particle, gives the walking rigid and deformable
// particles places in the contact order, as many as it holds; the force pass serves the particles
// in cell order, less those with a place, and then the contact order's, 32 walking particles to a
// warp. Teams of lanes share each particle's walk over its neighbour list: a tally and an atomic
// add a warp would cost the small scenes they serve more than their contact layers' walks, and
// they keep no contact order. No CUDA here, so the arrays' sizes and the force pass's seats are
// checked without a GPU (contact_order_test).
#include "../common/float_scene.hpp"
#include "../common/fluid_physics.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace mssph::kernels {

// What the density pass records of a sorted particle for the force pass.
enum ForceWalk : std::uint8_t {
  kNoWalk = 0,              // its sums are zero (may_feel_forces)
  kWalkInCellOrder = 1,     // the force pass serves it in cell order
  kWalkInContactOrder = 2,  // it holds a place in the contact order, which serves it
};

// The density pass's record, for the force pass.
struct ForceWalks {
  std::uint8_t* walk = nullptr;            // per sorted particle: ForceWalk
  std::uint32_t* contact_order = nullptr;  // `contact_capacity` places: sorted particle indices
  std::uint32_t* contact_taken = nullptr;  // places asked for this step, zero before the density pass
  std::uint32_t contact_capacity = 0;
};

// Whether the particles of `body` may walk in the contact order: rigid and deformable ones, which
// receive forces and take their own body at rest, so their force sums walk only with another body
// within h (may_feel_forces).
MSSPH_HD bool may_take_contact_place(const BodyParameters& body) {
  return receives_forces(body) && takes_own_body_at_rest(body);
}

// Whether a particle of `body` asks the density pass for a place in the contact order: one that
// may take a place, with another body within h.
MSSPH_HD bool asks_contact_place(const BodyParameters& body, bool near_other_body) {
  return near_other_body && may_take_contact_place(body);
}

// The walk of a particle with or without another body within h, given place `place` of the
// contact order (`capacity` or beyond: none).
MSSPH_HD ForceWalk force_walk_of(bool near_other_body, std::uint32_t place, std::uint32_t capacity) {
  return !near_other_body ? kNoWalk : place < capacity ? kWalkInContactOrder : kWalkInCellOrder;
}

// The particle a force-pass team serves: team `member` below the particle count serves sorted
// particle `member` unless it holds a place in the contact order; the teams after them serve the
// places taken. `walks`: whether its force sums may be anything but zero (may_feel_forces).
struct ForceSeat {
  std::uint32_t s;
  bool active;
  bool walks;
};
MSSPH_HD ForceSeat force_seat(const SortedView& view, const ForceWalks& walks, std::uint32_t member) {
  const std::uint32_t n = view.step.particle_count;
  if (member < n) {
    const std::uint8_t walk = walks.walk[member];
    return {member, walk != kWalkInContactOrder,
            may_feel_forces(view.bodies[body_of(view.position[member])], walk != kNoWalk)};
  }
  const std::uint32_t place = member - n;
  if (place >= walks.contact_capacity || place >= *walks.contact_taken) return {0, false, false};
  return {walks.contact_order[place], true, true};
}

// The contact order's places with `team_lanes` lanes a particle: none for teams; with one lane, a
// quarter of the scene's rigid and deformable particles (may_take_contact_place). Inside a large
// block nearly all of them walk nothing, and 4 bytes for each beside the ForceWalk byte would take
// the deformable 1M block just past its memory target; a walking particle beyond the capacity
// walks in cell order.
inline std::size_t contact_order_capacity(const FloatScene& scene, unsigned team_lanes) {
  if (team_lanes > 1) return 0;
  const auto bodies = static_cast<std::size_t>(std::count_if(
      scene.body.begin(), scene.body.end(), [&](std::uint32_t b) { return may_take_contact_place(scene.bodies[b]); }));
  return (bodies + 3) / 4;
}

}  // namespace mssph::kernels
