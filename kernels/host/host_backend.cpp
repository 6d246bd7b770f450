#include "host_backend.hpp"

#include "../common/elastic_physics.hpp"
#include "../common/fluid_physics.hpp"
#include "util/errors.hpp"
#include "util/host_info.hpp"
#include "util/phase_timer.hpp"


namespace mssph::kernels {
namespace {

Vec3 to_vec3(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

}  // namespace

HostBackend::HostBackend(ParticleSetup setup) : setup_(std::move(setup)), scene_(make_float_scene(setup_)) {
  const std::size_t n = setup_.size();
  cell_start_.assign(std::size_t{scene_.grid.cell_count()} + 1, 0);
  sorted_id_.resize(n);
  sorted_position_.resize(n);
  sorted_velocity_.resize(n);
  volume_pressure_.resize(n);
  interaction_force_.assign(n, Vec4{0, 0, 0, 0});
  elastic_force_.assign(n, Vec4{0, 0, 0, 0});
  const std::size_t deformables = scene_.deformable_body.size();
  rotation_.assign(deformables, Quat{0, 0, 0, 1});
  stress_action_.assign(deformables, zero_mat3());
  deformation_.assign(deformables, identity_mat3());
}

BackendInfo HostBackend::info() const { return {"cpu", host_cpu_name(), "float32"}; }

RigidBody& HostBackend::rigid_of(std::size_t body) {
  const std::uint32_t index = body < scene_.bodies.size() ? scene_.bodies[body].rigid_index : kNotRigid;
  if (index == kNotRigid) throw std::invalid_argument("body " + std::to_string(body) + " is not a movable rigid body");
  return scene_.rigid_bodies[index];
}

void HostBackend::set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  RigidBody& rigid = rigid_of(body);
  rigid.external_force = to_vec3(force);
  rigid.external_torque = to_vec3(torque);
}

SortedView HostBackend::sorted_view() const {
  return SortedView{scene_.step,           scene_.bodies.data(),
                    CellRanges{scene_.grid, cell_start_.data()},
                    sorted_position_.data(), sorted_velocity_.data(),
                    sorted_id_.data(),       volume_pressure_.data()};
}

// Counting sort of the particles by cell key (stable: equal keys keep canonical order), then the
// same cell table and cell-ordered copies as the CUDA backend.
void HostBackend::build_grid() {
  const std::size_t n = setup_.size();
  std::vector<std::uint32_t> key(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) key[i] = scene_.grid.key_of(xyz(scene_.position[i]));
  // The prefix sum of the cell counts is the cell table itself, as the GPU's scan makes it.
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[key[i] + 1];
  for (std::size_t k = 1; k < cell_start_.size(); ++k) cell_start_[k] += cell_start_[k - 1];
  std::vector<std::uint32_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted_id_[next[key[i]]++] = static_cast<std::uint32_t>(i);
  const auto count = static_cast<std::uint32_t>(n);
#pragma omp parallel for schedule(static)
  for (std::uint32_t s = 0; s < count; ++s) {
    place_in_cell_order(s, sorted_id_.data(), scene_.position.data(), scene_.velocity.data(), scene_.body.data(),
                        sorted_position_.data(), sorted_velocity_.data());
  }
}

DeformableView HostBackend::deformable_view() {
  return DeformableView{scene_.elastic_bodies.data(), scene_.deformable_body.data(), scene_.bond_start.data(),
                        scene_.bonds.data(),          scene_.rest_volume.data(),     scene_.position.data(),
                        scene_.velocity.data(),       rotation_.data(),              stress_action_.data(),
                        deformation_.data(),          elastic_force_.data(),
                        static_cast<std::uint32_t>(scene_.deformable_body.size())};
}

// Steps 1 and 3 of deformable bodies from the positions at the start of the step: all rotations
// and stresses first, since each elastic force reads its neighbours' stresses.
void HostBackend::compute_elasticity() {
  const DeformableView view = deformable_view();
#pragma omp parallel for schedule(static)
  for (std::uint32_t d = 0; d < view.count; ++d) rotation_and_stress(view, d);
#pragma omp parallel for schedule(static)
  for (std::uint32_t d = 0; d < view.count; ++d) elastic_force(view, d);
}

void HostBackend::compute_densities() {
  const SortedView view = sorted_view();
  const std::size_t n = setup_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const auto t = static_cast<std::uint32_t>(s);
    volume_pressure_[s] = density_from(density_sum(view, t, 0, 1), view, t).volume_pressure;
  }
}

void HostBackend::compute_forces_and_integrate() {
  const SortedView view = sorted_view();
  const CanonicalState state{scene_.position.data(), scene_.velocity.data(), interaction_force_.data(),
                             rotation_.empty() ? nullptr : elastic_force_.data(), scene_.body.data(), scene_.fixed.data()};
  const auto n = static_cast<std::uint32_t>(setup_.size());
#pragma omp parallel for schedule(static)
  for (std::uint32_t s = 0; s < n; ++s) apply_forces(view, state, s, force_sum(view, load_force_particle(view, s), 0, 1));
}

void HostBackend::advance_rigid_bodies() {
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

// Paper 3.2 on the kernels' functions: grid, rotations and elastic forces of deformable bodies,
// densities, forces with leap-frog integration of particles, then rigid-body dynamics.
void HostBackend::step() {
  {
    PhaseTimer timer(phase_seconds_[kNeighbours]);
    build_grid();
  }
  {
    PhaseTimer timer(phase_seconds_[kRotations]);
    compute_elasticity();
  }
  {
    PhaseTimer timer(phase_seconds_[kDensities]);
    compute_densities();
  }
  {
    PhaseTimer timer(phase_seconds_[kForces]);
    compute_forces_and_integrate();
  }
  {
    PhaseTimer timer(phase_seconds_[kIntegration]);
    advance_rigid_bodies();
  }
  time_ += setup_.dt;
}

ForceEvaluation HostBackend::evaluate_forces() {
  build_grid();
  compute_elasticity();
  compute_densities();
  const std::size_t n = setup_.size();
  ForceEvaluation out;
  out.density.resize(n);
  out.pressure.resize(n);
  out.pressure_force.resize(n);
  out.viscosity_force.resize(n);
  out.elastic_force.resize(n);
  out.rotation.assign(n, Eigen::Matrix3d::Identity());
  const SortedView view = sorted_view();
  const auto to_eigen = [](Vec3 v) { return Eigen::Vector3d(v.x, v.y, v.z); };
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t i = sorted_id_[s];
    const auto t = static_cast<std::uint32_t>(s);
    const ForceSum f = force_sum(view, load_force_particle(view, t), 0, 1);
    out.density[i] = scene_.bodies[scene_.body[i]].sph_mass / volume_pressure_[s].volume;
    out.pressure[i] = volume_pressure_[s].pressure;
    out.pressure_force[i] = to_eigen(f.pressure);
    out.viscosity_force[i] = to_eigen(f.viscosity);
    out.elastic_force[i] = to_eigen(xyz(elastic_force_[i]));
  }
  for (std::uint32_t d = 0; d < rotation_.size(); ++d) {
    const ElasticParameters& body = scene_.elastic_bodies[scene_.deformable_body[d]];
    const Mat3 r = rotation_matrix(rotation_[d]);
    Eigen::Matrix3d& out_r = out.rotation[body.first_particle + (d - body.first_deformable)];
    for (int k = 0; k < 9; ++k) out_r(k / 3, k % 3) = r.m[k];
  }
  return out;
}

void HostBackend::set_particle_positions(const std::vector<Eigen::Vector3d>& positions) {
  for (std::size_t i = 0; i < setup_.size(); ++i) {
    const std::uint32_t kind = scene_.bodies[scene_.body[i]].kind;
    if (kind == kFluid || kind == kDeformable) scene_.position[i] = make_vec4(scene_.to_kernel_frame(positions[i]), 0.0f);
  }
}

std::vector<BodyState> HostBackend::body_states() {
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    const BodySetup& body = setup_.bodies[b];
    BodySums sums = zero_body_sums();
    const float mass = scene_.bodies[b].sph_mass;
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      add_particle(sums, xyz(scene_.position[i]), xyz(scene_.velocity[i]), mass, xyz(interaction_force_[i]));
    }
    for (const ElasticParameters& elastic : scene_.elastic_bodies) {
      if (elastic.first_particle != body.first || body.kind != BodyKind::deformable) continue;
      for (std::size_t k = 0; k < body.count; ++k) {
        add_volume_ratio(sums, determinant(deformation_[elastic.first_deformable + k]), elastic.lowest_valid_volume_ratio);
      }
    }
    const std::uint32_t rigid = scene_.bodies[b].rigid_index;
    states.push_back(to_body_state(scene_, sums, rigid == kNotRigid ? nullptr : &scene_.rigid_bodies[rigid], body));
  }
  return states;
}

BodyState HostBackend::rigid_body_state(std::size_t body) {
  const RigidBody& rigid = rigid_of(body);
  BodySums sums = zero_body_sums();
  for (std::uint32_t i = rigid.first; i < rigid.first + rigid.count; ++i) {
    add_particle(sums, xyz(scene_.position[i]), xyz(scene_.velocity[i]), 0.0f, Vec3{0, 0, 0});
  }
  return to_body_state(scene_, sums, &rigid, setup_.bodies[body]);
}

ParticleSnapshot HostBackend::snapshot() {
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
    const VolumePressure vp = volume_pressure_[s];
    out.density[i] = vp.volume > 0.0f ? scene_.bodies[scene_.body[i]].sph_mass / vp.volume : 0.0f;
    out.pressure[i] = vp.pressure;
  }
  return out;
}

std::vector<double> HostBackend::last_phase_seconds() const { return {phase_seconds_.begin(), phase_seconds_.end()}; }

}  // namespace mssph::kernels
