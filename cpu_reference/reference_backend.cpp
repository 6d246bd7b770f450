#include "reference_backend.hpp"

#include "deformable_damping.hpp"
#include "density.hpp"
#include "elastic_forces.hpp"
#include "elasticity.hpp"
#include "fluid_forces.hpp"
#include "rigid_body_dynamics.hpp"
#include "util/host_info.hpp"
#include "util/phase_timer.hpp"
#include "wall_exclusion.hpp"
#include "zero_energy_control.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace mssph::reference {
ReferenceBackend::ReferenceBackend(ParticleSetup setup)
    : setup_(std::move(setup)), deformable_rest_(build_deformable_rest_state(setup_)) {
  particles_.resize(setup_.size());
  deformables_.resize(setup_.size());
  particles_.position = setup_.position;
  particles_.velocity = setup_.velocity;
  left_domain_.assign(setup_.size(), 0);
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    if (setup_.bodies[b].moves_as_rigid_body()) rigid_bodies_.push_back(make_rigid_body_state(setup_.bodies[b], b));
  }
}

BackendInfo ReferenceBackend::info() const { return {"reference", host_cpu_name(), "float64"}; }

RigidBodyState* ReferenceBackend::rigid_body_of(std::size_t body) {
  for (RigidBodyState& r : rigid_bodies_) {
    if (r.body == body) return &r;
  }
  return nullptr;
}

RigidBodyState& ReferenceBackend::movable_rigid_body(std::size_t body) {
  RigidBodyState* rigid = rigid_body_of(body);
  if (!rigid) throw std::invalid_argument("body " + std::to_string(body) + " is not a movable rigid body");
  return *rigid;
}

void ReferenceBackend::set_external_wrench(std::size_t body, const Eigen::Vector3d& force,
                                           const Eigen::Vector3d& torque) {
  RigidBodyState& rigid = movable_rigid_body(body);
  rigid.external_force = force;
  rigid.external_torque = torque;
}

// The neighbour search and steps 1-3 of paper 3.2, one phase per line with the shared phase names.
void ReferenceBackend::compute_forces() {
  timed(phase_seconds_[kNeighbours],
        [&] { neighbours_ = find_neighbours(particles_.position, setup_.smoothing_length); });
  timed(phase_seconds_[kRotations],
        [&] { compute_rotations(setup_, deformable_rest_, particles_.position, deformables_); });
  timed(phase_seconds_[kDensities], [&] {
    compute_densities(setup_, deformable_rest_.own_rest_number_density, neighbours_, particles_);
    compute_elastic_stresses(setup_, deformable_rest_, particles_.position, particles_.velocity, deformables_);
  });
  timed(phase_seconds_[kForces], [&] {
    if (setup_.viscosity_model == ViscosityModel::full_stress)
      compute_velocity_gradients(setup_, neighbours_, particles_);
    compute_pressure_viscosity_forces(setup_, neighbours_, particles_);
    add_deformable_forces();
    for (RigidBodyState& body : rigid_bodies_) sum_interaction_wrench(setup_, particles_, body);
  });
}

// The internal forces of deformable bodies: elasticity (eq. 5, 6) and, where configured,
// zero-energy-mode control and damping. They act within a body and go to internal_force.
void ReferenceBackend::add_deformable_forces() {
  compute_elastic_forces(setup_, deformable_rest_, deformables_);
  compute_zero_energy_forces(setup_, deformable_rest_, particles_.position, deformables_);
  compute_damping_forces(setup_, particles_, deformables_);
  for (const BodySetup& body : setup_.bodies) {
    if (body.kind != BodyKind::deformable) continue;
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      particles_.internal_force[i] +=
          deformables_.elastic_force[i] + deformables_.hourglass_force[i] + deformables_.damping_force[i];
    }
  }
}

// Paper 3.2: (1) rotations of deformable particles, (2) densities and elastic stresses,
// (3) internal and interaction forces, (4) integration: leap-frog for fluid and deformable
// particles, rigid-body dynamics for rigid bodies.
void ReferenceBackend::step() {
  compute_forces();                                           // neighbours, steps 1-3
  timed(phase_seconds_[kIntegration], [&] { integrate(); });  // step 4
  time_ += setup_.dt;
}

// Leap-frog with staggered velocities: v_{n+1/2} = v_{n-1/2} + a_n dt, x_{n+1} = x_n + v_{n+1/2} dt,
// where a_n = f_n / m + g, then kept out of the walls (wall_exclusion.hpp) and deactivated once
// outside the domain. Boundary, fixed and deactivated particles do not move; rigid particles
// follow their body.
void ReferenceBackend::integrate() {
  const double dt = setup_.dt;
  const std::size_t n = setup_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const BodySetup& body = setup_.bodies[setup_.body[i]];
    if (body.kind != BodyKind::fluid && body.kind != BodyKind::deformable) continue;
    if (setup_.fixed[i] || left_domain_[i]) {
      particles_.velocity[i].setZero();
      continue;
    }
    const Eigen::Vector3d force = particles_.internal_force[i] + particles_.interaction_force[i];
    const Eigen::Vector3d previous = particles_.position[i];
    particles_.velocity[i] += (force / setup_.mass[i] + setup_.gravity) * dt;
    particles_.position[i] += particles_.velocity[i] * dt;
    keep_out_of_walls(setup_, neighbours_, i, particles_.position, previous, particles_.position[i],
                      particles_.velocity[i]);
    deactivate_outside_domain(i);
  }
  for (RigidBodyState& body : rigid_bodies_) {
    integrate_rigid_body(body, setup_.gravity, dt);
    place_rigid_particles(setup_, body, particles_);
  }
}

// A fluid or deformable particle that has just left the simulation domain is held from now on
// where it left, with no velocity; it stays a neighbour of particles within h of that spot,
// outside the domain and away from the scene's bodies (float twin: kernels::deactivate_outside_domain).
void ReferenceBackend::deactivate_outside_domain(std::size_t i) {
  if (setup_.domain.contains(particles_.position[i])) return;
  left_domain_[i] = 1;
  particles_.velocity[i].setZero();
}

ForceEvaluation ReferenceBackend::evaluate_forces() {
  compute_forces();
  const std::size_t n = setup_.size();
  ForceEvaluation out;
  out.density = particles_.density;
  out.pressure = particles_.pressure;
  out.pressure_force = particles_.pressure_force;
  out.viscosity_force = particles_.viscosity_force;
  out.elastic_force.assign(n, Eigen::Vector3d::Zero());
  out.rotation.assign(n, Eigen::Matrix3d::Identity());
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup_, i)) continue;
    out.elastic_force[i] =
        deformables_.elastic_force[i] + deformables_.hourglass_force[i] + deformables_.damping_force[i];
    out.rotation[i] = deformables_.rotation[i];
  }
  return out;
}

void ReferenceBackend::set_particle_positions(const std::vector<Eigen::Vector3d>& positions) {
  for (std::size_t i = 0; i < setup_.size(); ++i) {
    const BodyKind kind = setup_.bodies[setup_.body[i]].kind;
    if (kind == BodyKind::fluid || kind == BodyKind::deformable) particles_.position[i] = positions[i];
  }
}

BodyState ReferenceBackend::rigid_body_state(std::size_t body) {
  const RigidBodyState* rigid = &movable_rigid_body(body);
  BodyState s;
  s.mass = rigid->mass;
  s.centre_of_mass = rigid->position;
  s.linear_momentum = rigid->mass * rigid->velocity;
  s.angular_momentum = rigid->angular_momentum;
  s.orientation = rigid->orientation;
  s.angular_velocity = rigid->angular_velocity();
  s.kinetic_energy =
      0.5 * rigid->mass * rigid->velocity.squaredNorm() + 0.5 * s.angular_velocity.dot(s.angular_momentum);
  s.interaction_force = rigid->interaction_force;
  s.interaction_torque = rigid->interaction_torque;
  const BodySetup& b = setup_.bodies[body];
  for (std::size_t i = b.first; i < b.first + b.count; ++i)
    s.max_speed = std::max(s.max_speed, particles_.velocity[i].norm());
  return s;
}

std::vector<BodyState> ReferenceBackend::body_states() {
  std::vector<BodyState> states(setup_.bodies.size());
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    if (rigid_body_of(b)) {
      states[b] = rigid_body_state(b);
      continue;
    }
    const BodySetup& body = setup_.bodies[b];
    BodyState& s = states[b];
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      s.max_speed = std::max(s.max_speed, particles_.velocity[i].norm());
      s.interaction_force += particles_.interaction_force[i];
      s.left_domain_count += left_domain_[i];
    }
    // Particle bodies (and static ones): mass-weighted sums with the SPH masses.
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      s.mass += setup_.mass[i];
      s.centre_of_mass += setup_.mass[i] * particles_.position[i];
    }
    s.centre_of_mass /= s.mass;
    if (body.kind == BodyKind::rigid) s.orientation = body.orientation;  // fixed rigid body
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      const Eigen::Vector3d arm = particles_.position[i] - s.centre_of_mass;
      s.linear_momentum += setup_.mass[i] * particles_.velocity[i];
      s.angular_momentum += setup_.mass[i] * arm.cross(particles_.velocity[i]);
      s.kinetic_energy += 0.5 * setup_.mass[i] * particles_.velocity[i].squaredNorm();
      s.interaction_torque += arm.cross(particles_.interaction_force[i]);
    }
    if (body.kind == BodyKind::deformable) {
      const double lowest_valid = lowest_valid_volume_ratio(body.material.model);
      s.min_volume_ratio = std::numeric_limits<double>::infinity();
      for (std::size_t i = body.first; i < body.first + body.count; ++i) {
        const double j = volume_ratio(deformables_.displacement_gradient[i]);
        s.min_volume_ratio = std::min(s.min_volume_ratio, j);
        if (j <= lowest_valid) ++s.compressed_count;
      }
    }
  }
  return states;
}

ParticleSnapshot ReferenceBackend::snapshot() {
  ParticleSnapshot out;
  const std::size_t n = setup_.size();
  out.position.reserve(3 * n);
  out.velocity.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      out.position.push_back(static_cast<float>(particles_.position[i][a]));
      out.velocity.push_back(static_cast<float>(particles_.velocity[i][a]));
    }
    out.density.push_back(static_cast<float>(particles_.density[i]));
    out.pressure.push_back(static_cast<float>(particles_.pressure[i]));
  }
  return out;
}

std::vector<double> ReferenceBackend::last_phase_seconds() const {
  return {phase_seconds_.begin(), phase_seconds_.end()};
}

}  // namespace mssph::reference
