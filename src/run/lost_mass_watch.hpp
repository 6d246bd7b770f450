#pragma once
// Watches fluid and deformable bodies for particles that left the simulation domain (the
// backends deactivate them: kernels/common/simulation_domain.hpp, the reference's integrate). At
// every check it records, per body, how many have left (/bodies/<name>/left_domain_count), and
// fails the run with SimulationFailure("N particles of body B left the domain ...") once they
// carry more than simulation/max_lost_mass_fraction of the body's mass. The particles of a fluid
// or deformable body all have the same mass (rho0 dx^3), so the mass fraction is the count's.
#include "backend/backend.hpp"
#include "backend/state_arrays.hpp"
#include "io/run_log.hpp"
#include "model/particle_setup.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace mssph {

class LostMassWatch {
 public:
  LostMassWatch(RunLog& log, const ParticleSetup& setup);

  // Every body's state (in body order) at simulated time `time` [s]: throws past the fraction.
  void check(const std::vector<BodyState>& states, double time);
  // One logged sample of every watched body: appends its count.
  void record(const std::vector<BodyState>& states);

  // Writes the per-body totals as attributes; "block 2 particles (0.03 %)" for the bodies that
  // lost any, "" when none did.
  std::string finish();

  // Checkpoints: each body's count at the last check.
  StateArrays save_state() const;
  void restore_state(const StateArrays& state);

 private:
  struct Watched {
    std::size_t body = 0;
    std::string name;
    std::size_t particles = 0;
    std::size_t series = 0;
    std::size_t left = 0;  // at the last check
  };
  RunLog& log_;
  double max_fraction_;
  std::vector<Watched> watched_;
};

}  // namespace mssph
