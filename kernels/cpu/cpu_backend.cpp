#include "cpu_backend.hpp"

#include "../common/eigen_conversion.hpp"
#include "../common/elastic_physics.hpp"
#include "../common/float_state.hpp"
#include "../common/fluid_physics.hpp"
#include "../common/list_skin.hpp"
#include "../common/neighbour_list.hpp"
#include "../common/read_back.hpp"
#include "util/host_info.hpp"
#include "util/phase_timer.hpp"

#include <cmath>

namespace mssph::kernels {

namespace {

// Particle p's pressure and viscosity sums over its list, with the transposed stress term where the
// scene's viscosity is full_stress (the pair loop is chosen once per particle).
ForceSum force_sum_of(const SortedView& view, const ForceParticle& p, const NeighbourLists& lists) {
  const auto candidates = neighbours_of(view, lists, p.s);
  return view.velocity_gradient != nullptr ? force_sum_over<true>(view, p, candidates)
                                           : force_sum_over<false>(view, p, candidates);
}

}  // namespace

CpuBackend::CpuBackend(ParticleSetup setup)
    : setup_(std::move(setup)), scene_(make_float_scene_with_list_cells(setup_)) {
  const std::size_t n = setup_.size();
  cell_start_.assign(std::size_t{scene_.grid.cell_count()} + 1, 0);
  cell_middle_.assign(scene_.grid.cell_count(), 0);
  sorted_id_.resize(n);
  sorted_position_.resize(n);
  sorted_velocity_.resize(n);
  volume_pressure_.resize(n);
  if (scene_.full_stress_viscosity) velocity_gradient_.assign(n, zero_mat3());
  recorded_count_.resize(n);
  recorded_index_.resize(n * kNeighbourCapacity);
  neighbour_count_.resize(n);
  neighbour_index_.resize(n * kNeighbourCapacity);
  list_origin_.resize(n);
  interaction_force_.assign(n, Vec4{0, 0, 0, 0});
  elastic_force_.assign(n, Vec4{0, 0, 0, 0});
  const std::size_t deformables = scene_.deformable_body.size();
  rotation_.assign(deformables, Quat{0, 0, 0, 1});
  corrected_stress_action_.assign(deformables, zero_mat3());
  deformation_.assign(deformables, identity_mat3());
}

BackendInfo CpuBackend::info() const { return {"cpu", host_cpu_name(), "float32"}; }

RigidBody& CpuBackend::rigid_of(std::size_t body) { return scene_.rigid_bodies[movable_rigid_index(scene_, body)]; }

void CpuBackend::set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  RigidBody& rigid = rigid_of(body);
  rigid.external_force = to_vec3(force);
  rigid.external_torque = to_vec3(torque);
}

SortedView CpuBackend::sorted_view() const {
  return SortedView{scene_.step,
                    scene_.bodies.data(),
                    CellRanges{scene_.grid, cell_start_.data(), nullptr, cell_middle_.data()},
                    sorted_position_.data(),
                    sorted_velocity_.data(),
                    sorted_id_.data(),
                    volume_pressure_.data(),
                    scene_.own_rest_number_density.empty() ? nullptr : scene_.own_rest_number_density.data(),
                    velocity_gradient_.empty() ? nullptr : velocity_gradient_.data()};
}

NeighbourLists CpuBackend::recorded_lists() {
  return particle_lists(kNeighbourCapacity, recorded_count_.data(), recorded_index_.data());
}

NeighbourLists CpuBackend::neighbour_lists() {
  return particle_lists(kNeighbourCapacity, neighbour_count_.data(), neighbour_index_.data());
}

// The neighbours phase: the particles copied into the cell order of the last rebuild, whose lists
// are kept until some particle has moved past its body's trigger (list_skin.hpp); then the grid is
// rebuilt and the lists recorded again. The density pass copies each list's entries within h for
// the force pass (density_sum_keeping_within), so that the force pair's branch on h, which the
// host mispredicts for about one entry in four of a list with a skin, does not run over the
// recorded lists themselves.
void CpuBackend::update_neighbour_lists() {
  if (rebuild_requested_ || lists_expired()) build_grid();
}

// Copies every particle into the last rebuild's cell order and returns whether one has moved past
// its body's trigger since.
bool CpuBackend::lists_expired() {
  const float* trigger2 = scene_.list_trigger2.data();
  const auto count = static_cast<std::uint32_t>(setup_.size());
  bool moved_far = false;
#pragma omp parallel for schedule(static) reduction(|| : moved_far)
  for (std::uint32_t s = 0; s < count; ++s) {
    place_in_cell_order(s, sorted_id_[s], scene_.position.data(), scene_.velocity.data(), scene_.body.data(),
                        sorted_position_.data(), sorted_velocity_.data());
    const Vec4 p = sorted_position_[s];
    if (moved_past_trigger(xyz(p), xyz(list_origin_[s]), trigger2[body_of(p)])) moved_far = true;
  }
  return moved_far;
}

// Counting sort of the particles by cell key and, within a cell, by half along x (stable: equal
// keys keep canonical order), then the same cell table, halves and cell-ordered copies as the
// CUDA backend, then every particle's list of the candidates within h + skin, which the density
// pass visits instead of the 27 cells until the lists expire (copying the entries within h for the
// force pass), and the threads' shares of the loops over them (partition_by_list_length). The
// halves let the list's walk trim half a cell at each end of a row (CellRanges::cell_middle), 2.5
// cells of 3, as the GPU's one-lane walks do.
void CpuBackend::build_grid() {
  const std::size_t n = setup_.size();
  const std::size_t cells = scene_.grid.cell_count();
  std::vector<std::uint32_t> half_key(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) half_key[i] = scene_.grid.half_key_of(xyz(scene_.position[i]));
  // The prefix sum of the halves' counts gives the cell table and the halves' boundaries, as the
  // GPU's scan makes them.
  std::vector<std::uint32_t> half_start(2 * cells + 1, 0u);
  for (std::size_t i = 0; i < n; ++i) ++half_start[half_key[i] + 1];
  for (std::size_t k = 1; k < half_start.size(); ++k) half_start[k] += half_start[k - 1];
  for (std::size_t k = 0; k < cells; ++k) {
    cell_start_[k] = half_start[2 * k];
    cell_middle_[k] = half_start[2 * k + 1];
  }
  cell_start_[cells] = half_start[2 * cells];
  std::vector<std::uint32_t> next(half_start.begin(), half_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted_id_[next[half_key[i]]++] = static_cast<std::uint32_t>(i);
  const auto count = static_cast<std::uint32_t>(n);
#pragma omp parallel for schedule(static)
  for (std::uint32_t s = 0; s < count; ++s) {
    place_in_cell_order(s, sorted_id_[s], scene_.position.data(), scene_.velocity.data(), scene_.body.data(),
                        sorted_position_.data(), sorted_velocity_.data());
  }
  const SortedView view = sorted_view();
  const NeighbourLists lists = recorded_lists();
  const float record_radius2 = list_skin(scene_.step.smoothing.h).record_radius2;
  bool overflowed = false;
#pragma omp parallel for schedule(static) reduction(|| : overflowed)
  for (std::uint32_t s = 0; s < count; ++s) {
    record_neighbours(view, lists, s, record_radius2, body_left_out(view, view.position[s]));
    if (lists.count[s] >= lists.capacity) overflowed = true;
  }
  list_origin_ = sorted_position_;
  partition_by_list_length();
  rebuild_requested_ = overflowed;  // an overflowed list is walked on this step's fresh grid only
  ++grid_builds_;
}

// The loops over the lists split by their lengths until the next rebuild (particle_partition.hpp):
// a particle's sums cost about one unit per recorded neighbour, plus its own loads and stores,
// taken as kParticleCost units; a boundary particle's force pass, which sums nothing, that alone.
void CpuBackend::partition_by_list_length() {
  constexpr std::uint32_t kParticleCost = 4;
  const SortedView view = sorted_view();
  const auto count = static_cast<std::uint32_t>(setup_.size());
  const std::uint32_t parts = ParticlePartition::for_current_threads();
  density_partition_.assign(count, parts, [&](std::uint32_t s) { return kParticleCost + recorded_count_[s]; });
  force_partition_.assign(count, parts, [&](std::uint32_t s) {
    const bool sums = receives_forces(view.bodies[body_of(view.position[s])]);
    return kParticleCost + (sums ? recorded_count_[s] : 0u);
  });
}

HostDeformableView CpuBackend::deformable_view() {
  return HostDeformableView{scene_.elastic_bodies.data(),
                            scene_.deformable_body.data(),
                            scene_.bond_count.data(),
                            scene_.bond_neighbour.data(),
                            scene_.rest.data(),
                            scene_.correction.data(),
                            scene_.step.smoothing,
                            scene_.position.data(),
                            scene_.velocity.data(),
                            rotation_.data(),
                            Mat3Records{corrected_stress_action_.data()},
                            deformation_.data(),
                            elastic_force_.data(),
                            static_cast<std::uint32_t>(scene_.deformable_body.size())};
}

// Step 1, R_i of deformable particles, with their stresses and elastic forces (step 3 of
// deformable bodies) from the positions at the start of the step: all rotations and stresses
// first, since each elastic force reads its neighbours' stresses.
void CpuBackend::compute_rotations_and_elastic_forces() {
  const HostDeformableView view = deformable_view();
#pragma omp parallel for schedule(static)
  for (std::uint32_t d = 0; d < view.count; ++d) rotation_and_stress(view, d);
#pragma omp parallel for schedule(static)
  for (std::uint32_t d = 0; d < view.count; ++d) elastic_force(view, d);
}

// Step 2, densities and pressures (eq. 1 and the equation of state), in cell order, over the
// recorded lists, whose entries within h each particle's sum copies for the force pass; then, for
// the full_stress viscosity, each fluid particle's velocity gradient, which reads those volumes.
void CpuBackend::compute_densities() {
  const SortedView view = sorted_view();
  const NeighbourLists recorded = recorded_lists(), within = neighbour_lists();
  density_partition_.for_each([&](std::uint32_t s) {
    const DensitySum sum = density_sum_keeping_within(view, recorded, within, s);
    volume_pressure_[s] = density_from(sum, view, s, body_left_out(view, view.position[s])).volume_pressure;
  });
  if (velocity_gradient_.empty()) return;
  density_partition_.for_each([&](std::uint32_t s) {
    velocity_gradient_[s] = velocity_gradient_sums_over(view, s, neighbours_of(view, within, s)).gradient();
  });
}

// Step 3, pressure and viscosity forces (eq. 2, 3, 7), each particle then advanced by step 4's
// leap-frog in the same pass.
void CpuBackend::compute_forces_and_advance_particles() {
  const SortedView view = sorted_view();
  const CanonicalState state{scene_.position.data(), scene_.velocity.data(), interaction_force_.data(),
                             rotation_.empty() ? nullptr : elastic_force_.data(), scene_.fixed.data()};
  const NeighbourLists lists = neighbour_lists();
  force_partition_.for_each([&](std::uint32_t s) {
    const ForceParticle particle = load_force_particle(view, s);
    apply_forces(view, state, particle, force_sum_of(view, particle, lists));
  });
}

// Step 4 of rigid bodies: the interaction wrench of their particles, rigid-body dynamics, then
// their particles placed on the moved body.
void CpuBackend::advance_rigid_bodies() {
  for (RigidBody& body : scene_.rigid_bodies) {
    Wrench wrench{{0, 0, 0}, {0, 0, 0}};
    for (std::uint32_t i = body.first; i < body.first + body.count; ++i) {
      wrench = wrench + particle_wrench(xyz(scene_.position[i]), xyz(interaction_force_[i]), body.position);
    }
    body.interaction_force = wrench.force;
    body.interaction_torque = wrench.torque;
    integrate_rigid_body(body, scene_.step.gravity, scene_.step.dt);
    const Mat3 rotation = rotation_matrix(body.orientation);
    const Vec3 omega = angular_velocity(body);
#pragma omp parallel for schedule(static)
    for (std::uint32_t i = body.first; i < body.first + body.count; ++i) {
      place_rigid_particle(body, rotation, omega, xyz(scene_.rest_offset[i]), scene_.position[i], scene_.velocity[i]);
    }
  }
}

// Paper 3.2 on the kernels' functions, one phase per line with the shared phase names.
void CpuBackend::step() {
  timed(phase_seconds_[kNeighbours], [&] { update_neighbour_lists(); });
  timed(phase_seconds_[kRotations], [&] { compute_rotations_and_elastic_forces(); });  // step 1
  timed(phase_seconds_[kDensities], [&] { compute_densities(); });                     // step 2
  timed(phase_seconds_[kForces], [&] { compute_forces_and_advance_particles(); });     // step 3 (+ 4: leap-frog)
  timed(phase_seconds_[kIntegration], [&] { advance_rigid_bodies(); });                // step 4: rigid bodies
  time_ += setup_.dt;
}

// Steps up to the force sums, which are returned in canonical order instead of being integrated,
// on a grid rebuilt where the particles stand.
ForceEvaluation CpuBackend::evaluate_forces() {
  rebuild_requested_ = true;
  update_neighbour_lists();
  compute_rotations_and_elastic_forces();
  compute_densities();
  const SortedView view = sorted_view();
  const NeighbourLists lists = neighbour_lists();
  std::vector<ForceSum> sums(setup_.size());
  const auto n = static_cast<std::uint32_t>(setup_.size());
#pragma omp parallel for schedule(static)
  for (std::uint32_t s = 0; s < n; ++s) sums[s] = force_sum_of(view, load_force_particle(view, s), lists);
  return pack_force_evaluation(scene_, sorted_id_, volume_pressure_, sums, elastic_force_, rotation_);
}

void CpuBackend::set_particle_positions(const std::vector<Eigen::Vector3d>& positions) {
  for (std::size_t i = 0; i < setup_.size(); ++i) {
    const std::uint32_t kind = scene_.bodies[scene_.body[i]].kind;
    if (kind != kFluid && kind != kDeformable) continue;
    scene_.position[i] = make_vec4(scene_.to_kernel_frame(positions[i]), 0.0f);
    scene_.velocity[i].w = 0.0f;  // no carry: the position is a new start (compensated_position.hpp)
  }
  rebuild_requested_ = true;
}

StateArrays CpuBackend::save_state() {
  FloatRunState run;
  run.position = scene_.position;
  run.velocity = scene_.velocity;
  run.fixed = scene_.fixed;
  run.rigid_bodies = scene_.rigid_bodies;
  run.rotation = rotation_;
  run.time = time_;
  run.steps = static_cast<std::uint64_t>(std::llround(time_ / setup_.dt));
  // The lists' origin back in canonical order: the positions the last rebuild sorted (before the
  // first, any: that step rebuilds).
  run.list_origin = grid_builds_ > 0 ? list_origin_in_canonical_order(list_origin_, sorted_id_) : scene_.position;
  run.list_rebuild_requested = rebuild_requested_ ? 1 : 0;
  return save_float_state(run);
}

void CpuBackend::restore_state(const StateArrays& state) {
  FloatRunState restored = restore_float_state(state, scene_, true);
  // The saved run's lists: the grid rebuilt where the particles stood at its last rebuild gives the
  // same cell order and lists, so the restarted run sums as the saved one did.
  scene_.position = std::move(restored.list_origin);
  build_grid();
  rebuild_requested_ = restored.list_rebuild_requested != 0;
  scene_.position = std::move(restored.position);
  scene_.velocity = std::move(restored.velocity);
  scene_.fixed = std::move(restored.fixed);
  scene_.rigid_bodies = std::move(restored.rigid_bodies);
  rotation_ = std::move(restored.rotation);
  time_ = restored.time;
}

std::vector<BodyState> CpuBackend::body_states() {
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    const BodySetup& body = setup_.bodies[b];
    BodySums sums = zero_body_sums();
    const float mass = scene_.bodies[b].sph_mass;
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      add_particle(sums, xyz(scene_.position[i]), xyz(scene_.velocity[i]), mass, xyz(interaction_force_[i]));
      add_domain_status(sums, scene_.fixed[i]);
    }
    for (const ElasticParameters& elastic : scene_.elastic_bodies) {
      if (elastic.first_particle != body.first || body.kind != BodyKind::deformable) continue;
      for (std::size_t k = 0; k < body.count; ++k) {
        add_volume_ratio(sums, determinant(deformation_[elastic.first_deformable + k]),
                         elastic.lowest_valid_volume_ratio);
      }
    }
    const std::uint32_t rigid = scene_.bodies[b].rigid_index;
    states.push_back(to_body_state(scene_, sums, rigid == kNotRigid ? nullptr : &scene_.rigid_bodies[rigid], body));
  }
  return states;
}

BodyState CpuBackend::rigid_body_state(std::size_t body) {
  const RigidBody& rigid = rigid_of(body);
  BodySums sums = zero_body_sums();
  for (std::uint32_t i = rigid.first; i < rigid.first + rigid.count; ++i) {
    add_particle(sums, xyz(scene_.position[i]), xyz(scene_.velocity[i]), 0.0f, Vec3{0, 0, 0});
  }
  return to_body_state(scene_, sums, &rigid, setup_.bodies[body]);
}

ParticleSnapshot CpuBackend::snapshot() {
  const std::size_t n = setup_.size();
  ParticleSnapshot out;
  out.position.resize(3 * n);
  out.velocity.resize(3 * n);
  out.density.resize(n);
  out.pressure.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d world = scene_.to_world(xyz(scene_.position[i]));
    const float p[3] = {static_cast<float>(world.x()), static_cast<float>(world.y()), static_cast<float>(world.z())};
    const float v[3] = {scene_.velocity[i].x, scene_.velocity[i].y, scene_.velocity[i].z};
    for (int a = 0; a < 3; ++a) {
      out.position[3 * i + static_cast<std::size_t>(a)] = p[a];
      out.velocity[3 * i + static_cast<std::size_t>(a)] = v[a];
    }
  }
  // Densities and pressures of the last force evaluation, scattered back to canonical order.
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t i = sorted_id_[s];
    out.density[i] = particle_density(scene_, i, volume_pressure_[s]);
    out.pressure[i] = volume_pressure_[s].pressure;
  }
  return out;
}

std::vector<double> CpuBackend::last_phase_seconds() const { return {phase_seconds_.begin(), phase_seconds_.end()}; }

}  // namespace mssph::kernels
