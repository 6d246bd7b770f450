#pragma once
// The float32 starting state shared by the `cpu` and `cuda` backends: a ParticleSetup converted
// to the kernels' layout, the neighbour grid's shape, and the conversion of per-body sums back to
// mssph::BodyState.
#include "backend/backend.hpp"
#include "body_sums.hpp"
#include "cell_grid.hpp"
#include "elastic_physics.hpp"
#include "model/particle_setup.hpp"
#include "particle_views.hpp"
#include "rigid_physics.hpp"

#include <vector>

namespace mssph::kernels {

// Positions in the kernels are relative to `origin`, the centre of the scene's starting bounding
// box, so float32 keeps its resolution (about 1e-7 of the distance to the origin) for elastic
// displacements wherever the scene sits in the world.
struct FloatScene {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // world position of the kernels' origin [m]
  StepParameters step;
  GridShape grid;
  std::vector<BodyParameters> bodies;
  std::vector<RigidBody> rigid_bodies;  // movable rigid bodies, in body order
  bool full_stress_viscosity = false;   // viscosity_model full_stress: the force pass adds the transposed stress
  std::vector<float> list_trigger2;     // per body, with neighbour lists (list_triggers2), else empty [m^2]
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
  // Deformable particle d has bond_count[d] rest neighbours; its k-th is bond_neighbour[k * D + d] for
  // D deformable particles: bond-major, padded to the longest list, so that the threads of
  // neighbouring particles read neighbouring entries (one coalesced load per bond and warp instead
  // of one per thread). What else a bond needs is derived from the rest state (elastic_physics.hpp,
  // rest_bond).
  std::vector<std::uint32_t> bond_count;
  std::vector<std::uint32_t> bond_neighbour;  // canonical indices
  std::vector<Vec4> rest;                     // per deformable particle: X_i in the kernels' frame [m], w: V0_i [m^3]
  std::vector<Mat3> correction;               // per deformable particle: L_i, the kernel-gradient correction
  // The own-body number density at rest [1/m^3] of each particle of a rigid, deformable or boundary
  // body (model/deformable_rest_state.hpp; fluid_physics.hpp, takes_own_body_at_rest), in canonical
  // order with the fluid particles left out: particle i's at i less its body's own_rest_offset;
  // empty without such bodies.
  std::vector<float> own_rest_number_density;

  Vec3 to_kernel_frame(const Eigen::Vector3d& world) const {
    const Eigen::Vector3d local = world - origin;
    return {static_cast<float>(local.x()), static_cast<float>(local.y()), static_cast<float>(local.z())};
  }
  Eigen::Vector3d to_world(Vec3 local) const { return origin + Eigen::Vector3d(local.x, local.y, local.z); }
};

// Throws InputError for what the float backends do not run: damping of a deformable body that no
// fixed region holds (it needs the body's rigid motion every step; the reference has it).
FloatScene make_float_scene(const ParticleSetup& setup);
// The same for a backend whose neighbour lists have a skin (list_skin.hpp): cells h + skin wide, so
// that a rebuild's walk of 27 cells sees every candidate within h + skin; and each body's trigger
// (list_trigger2).
FloatScene make_float_scene_with_list_cells(const ParticleSetup& setup);

// Grid bits per axis: enough cells of side h to cover the starting bounding box (at least 4 per
// axis), with at most about 2 cells per particle in all so the cell table stays small. Positions
// in the kernels' frame.
GridShape choose_grid_shape(const std::vector<Vec4>& positions, double h);

// A body's logged state, in world coordinates, from its particle sums, or from its rigid-body
// state when it moves as one.
BodyState to_body_state(const FloatScene& scene, const BodySums& sums, const RigidBody* rigid, const BodySetup& body);

}  // namespace mssph::kernels
