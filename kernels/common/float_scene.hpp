#pragma once
// The float32 starting state shared by the `cpu` and `cuda` backends: a ParticleSetup converted
// to the kernels' layout, the neighbour grid's shape, and the conversion of per-body sums back to
// mssph::BodyState.
#include "body_sums.hpp"
#include "cell_grid.hpp"
#include "elastic_physics.hpp"
#include "particle_views.hpp"
#include "rigid_physics.hpp"
#include "scene/particle_setup.hpp"
#include "sim/backend.hpp"

#include <vector>

namespace mssph::kernels {

struct FloatScene {
  StepParameters step;
  GridShape grid;
  std::vector<BodyParameters> bodies;
  std::vector<RigidBody> rigid_bodies;  // movable rigid bodies, in body order
  // Canonical particle arrays.
  std::vector<Vec4> position;
  std::vector<Vec4> velocity;
  std::vector<Vec4> rest_offset;  // rigid particles: offset from the centre of mass, body frame
  std::vector<std::uint32_t> body;
  std::vector<std::uint8_t> fixed;

  // Deformable bodies (empty without them): per deformable body, then per deformable particle in
  // canonical order, and the rest bonds of each.
  std::vector<ElasticParameters> elastic_bodies;
  std::vector<std::uint32_t> deformable_body;  // index into elastic_bodies
  std::vector<std::uint32_t> bond_start;       // deformable particle d: bonds[bond_start[d] .. bond_start[d + 1])
  std::vector<RestBond> bonds;
  std::vector<float> rest_volume;              // V0 [m^3]
};

// Throws InputError for what the float backends do not run: damping of a deformable body that no
// fixed region holds (it needs the body's rigid motion every step; the reference has it).
FloatScene make_float_scene(const ParticleSetup& setup);

// Grid bits per axis: enough cells of side h to cover the starting bounding box (at least 4 per
// axis), with at most about 2 cells per particle in all so the cell table stays small.
GridShape choose_grid_shape(const std::vector<Vec4>& positions, double h);

// A body's logged state from its particle sums, or from its rigid-body state when it moves as one.
BodyState to_body_state(const BodySums& sums, const RigidBody* rigid, const BodySetup& body);

}  // namespace mssph::kernels
