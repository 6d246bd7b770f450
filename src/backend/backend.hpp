#pragma once
// What every backend (reference, cpu, cuda) offers the simulation driver: one step of the
// paper's loop (section 3.2), body-level state for logs and haptics, and particle snapshots.
#include "model/particle_setup.hpp"
#include "state_arrays.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mssph {

struct BackendInfo {
  std::string name;       // "reference", "cpu", "cuda"
  std::string device;     // CPU or GPU model
  std::string precision;  // "float64" or "float32"
};

// Body-level state at the current time, world frame, SI units.
struct BodyState {
  double mass = 0.0;                                           // [kg]
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();    // [m]
  Eigen::Vector3d linear_momentum = Eigen::Vector3d::Zero();   // [kg m/s]
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();  // about the centre of mass [kg m^2/s]
  double kinetic_energy = 0.0;                                 // [J]
  double max_speed = 0.0;                                      // fastest particle [m/s]
  // Rigid bodies: orientation and angular velocity (identity and zero for other kinds).
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // [rad/s]
  // Sum of the forces other bodies exert on this body's particles (paper eq. 7), and their
  // torque about the centre of mass (paper eq. 8, 9 without the device term) [N], [N m].
  Eigen::Vector3d interaction_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d interaction_torque = Eigen::Vector3d::Zero();
  // Deformable bodies: the compression of their particles' neighbourhoods as the volume ratio
  // J = det F = det(I + grad u) of paper eq. 4's displacement gradient (1 at rest, 0 collapsed,
  // negative inverted), from the last step's elastic forces. Other bodies keep 1 and 0.
  double min_volume_ratio = 1.0;     // smallest J over the body's particles [-]
  std::size_t compressed_count = 0;  // particles with J <= lowest_valid_volume_ratio(model) (config/elastic_model.hpp)
  // Fluid and deformable bodies: particles deactivated since they left the simulation domain.
  std::size_t left_domain_count = 0;
};

// Particle fields for snapshots, in particle order.
struct ParticleSnapshot {
  std::vector<float> position;  // 3 per particle [m]
  std::vector<float> velocity;  // 3 per particle [m/s]
  std::vector<float> density;   // [kg/m^3]
  std::vector<float> pressure;  // [Pa]
};

// One force evaluation at the current state, without stepping, per particle in canonical order:
// what backends are compared on (tests, validation).
struct ForceEvaluation {
  std::vector<double> density;                   // [kg/m^3]
  std::vector<double> pressure;                  // [Pa]
  std::vector<Eigen::Vector3d> pressure_force;   // paper eq. 2 and the pressure part of eq. 7 [N]
  std::vector<Eigen::Vector3d> viscosity_force;  // paper eq. 3 and the viscosity part of eq. 7 [N]
  std::vector<Eigen::Vector3d> elastic_force;  // deformable bodies' own forces: eq. 6, zero-energy control, damping [N]
  std::vector<Eigen::Matrix3d> rotation;       // R_i of deformable particles, identity elsewhere
};

class Backend {
 public:
  virtual ~Backend() = default;

  virtual BackendInfo info() const = 0;
  virtual std::size_t particle_count() const = 0;
  virtual double time() const = 0;  // simulated time [s]

  // An external wrench on a movable rigid body (the haptic coupling, paper eq. 8, 9), applied at
  // its centre of mass in every step until it is set again [N], [N m].
  virtual void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) = 0;

  // One time step dt: neighbour search, rotations, densities, forces, integration.
  virtual void step() = 0;

  // State of every body (one reduction over all particles).
  virtual std::vector<BodyState> body_states() = 0;
  // State of one movable rigid body, e.g. the haptic proxy: cheap enough to call every haptic
  // tick (a GPU backend copies one small record).
  virtual BodyState rigid_body_state(std::size_t body) = 0;
  virtual ParticleSnapshot snapshot() = 0;

  // For comparisons between backends: forces at the current state without stepping, and a way to
  // start from a deformed state (positions of fluid and deformable particles, canonical order;
  // other particles keep theirs).
  virtual ForceEvaluation evaluate_forces() = 0;
  virtual void set_particle_positions(const std::vector<Eigen::Vector3d>& positions) = 0;

  // Checkpoints: everything a later step reads that earlier steps wrote (positions, velocities,
  // rigid bodies, deactivated particles, the time, and what an iteration starts from, such as the
  // float backends' last rotations), so that a backend of the same setup restored from its own
  // save steps on bit-identically. restore_state throws InputError naming a missing or mis-sized
  // array.
  virtual StateArrays save_state() = 0;
  virtual void restore_state(const StateArrays& state) = 0;

  // Blocks until queued work is done: a GPU backend returns from step() before the step has run.
  virtual void synchronize() {}

  // How many times the neighbour grid was built since the backend was made, where a backend builds
  // it only on some steps: the cuda backend's teams keep neighbour lists with a skin and rebuild
  // when they expire (kernels/common/list_skin.hpp). Empty when it is built every step.
  virtual std::optional<std::uint64_t> neighbour_grid_builds() { return std::nullopt; }

  // The size of one step where a backend replays it as a captured graph (the cuda backend): all
  // its nodes, and of them the kernels. Empty where a step runs as host code.
  struct StepGraphSize {
    std::size_t nodes = 0;
    std::size_t kernels = 0;
  };
  virtual std::optional<StepGraphSize> step_graph_size() const { return std::nullopt; }

  // The step's phases, the same for every backend so that `/timing/phases` compare by name:
  // the paper's loop (3.2) after the neighbour search.
  //   neighbours   the neighbour search (the float backends' cell grid);
  //   rotations    step 1, R_i of deformable particles (the float backends also compute the
  //                elastic stresses and forces here, one pass over the rest bonds each);
  //   densities    step 2 (the reference also computes its elastic stresses here);
  //   forces       step 3 (the float backends also advance fluid and deformable particles here:
  //                step 4's leap-frog is fused into the force pass);
  //   integration  step 4 (the float backends: rigid bodies only).
  enum Phase : std::size_t { kNeighbours, kRotations, kDensities, kForces, kIntegration, kPhaseCount };
  static std::vector<std::string> phase_names() {
    return {"neighbours", "rotations", "densities", "forces", "integration"};
  }
  // Wall-clock seconds of each phase of the last step, in the order of phase_names(), while phase
  // timing is on; NaN for a phase a backend did not time.
  virtual std::vector<double> last_phase_seconds() const = 0;
  // Per-phase timing is off unless asked for: a GPU backend times its phases with events recorded
  // between them, which lengthen a small scene's step noticeably and make reading them wait for
  // the step. Host backends read a clock per phase either way.
  virtual void set_phase_timing(bool on) { (void)on; }
};

}  // namespace mssph
