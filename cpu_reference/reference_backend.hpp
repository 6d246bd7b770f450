#pragma once
// The double-precision reference backend: the oracle every other backend is checked against.
// step() is the paper's four-step loop (section 3.2), written for reading.
#include "backend/backend.hpp"
#include "deformable_state.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/neighbour_search.hpp"
#include "particle_state.hpp"

#include <array>
#include <chrono>

namespace mssph::reference {

class ReferenceBackend final : public Backend {
 public:
  explicit ReferenceBackend(ParticleSetup setup);

  BackendInfo info() const override;
  std::size_t particle_count() const override { return setup_.size(); }
  double time() const override { return time_; }
  void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override;
  void step() override;
  std::vector<BodyState> body_states() override;
  BodyState rigid_body_state(std::size_t body) override;
  ParticleSnapshot snapshot() override;
  std::vector<double> last_phase_seconds() const override;
  ForceEvaluation evaluate_forces() override;
  void set_particle_positions(const std::vector<Eigen::Vector3d>& positions) override;
  StateArrays save_state() override;
  void restore_state(const StateArrays& state) override;

  // For tests and validation: the full state.
  const ParticleSetup& setup() const { return setup_; }
  const ParticleState& particles() const { return particles_; }
  ParticleState& particles() { return particles_; }
  const std::vector<RigidBodyState>& rigid_bodies() const { return rigid_bodies_; }
  std::vector<RigidBodyState>& rigid_bodies() { return rigid_bodies_; }
  // Deformable bodies: the rest configuration and the last step's rotations, strains, stresses,
  // strain energies and forces.
  const DeformableRestState& deformable_rest() const { return deformable_rest_; }
  const DeformableState& deformables() const { return deformables_; }

  // Steps 1-3 of a step without integrating: neighbours, rotations, densities and forces for the
  // current positions and velocities (used by step() and by one-step comparisons between backends).
  void compute_forces();

 private:
  void add_deformable_forces();
  void integrate();
  void deactivate_outside_domain(std::size_t i);
  RigidBodyState* rigid_body_of(std::size_t body);       // nullptr unless `body` moves as a rigid body
  RigidBodyState& movable_rigid_body(std::size_t body);  // throws std::invalid_argument unless it does

  ParticleSetup setup_;
  ParticleState particles_;
  std::vector<RigidBodyState> rigid_bodies_;  // movable rigid bodies only
  std::vector<std::uint8_t> left_domain_;     // 1: deactivated after leaving the simulation domain
  DeformableRestState deformable_rest_;
  DeformableState deformables_;
  NeighbourLists neighbours_;
  double time_ = 0.0;
  std::array<double, kPhaseCount> phase_seconds_{};
};

}  // namespace mssph::reference
