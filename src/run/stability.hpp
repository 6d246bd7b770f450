#pragma once
// Start-up checks of the explicit time step against the CFL-type bounds of docs/model.md:
// acoustic 0.25 h / (c + v), viscous 0.125 h^2 rho / mu, body force 0.25 sqrt(h / |g|),
// elastic 0.25 h / c_p and viscoelastic 0.05 h^2 rho / ((eta / E) (lambda + 2 mu)). A violated bound is a warning (the
// run may still be stable); a run that then blows up fails with exit code 3.
#include "model/particle_setup.hpp"

#include <string>
#include <vector>

namespace mssph {

// One upper bound on the time step: which body (or "(all)"), which bound, its value [s] and
// formula with the numbers that went into it.
struct TimeStepBound {
  std::string body;
  std::string name;  // "acoustic", "viscous", "body-force", "elastic", "viscoelastic"
  double limit = 0.0;
  std::string formula;
};
std::vector<TimeStepBound> time_step_bounds(const ParticleSetup& setup);

// One warning per bound dt exceeds, and for nearly incompressible elastic bodies.
std::vector<std::string> stability_warnings(const ParticleSetup& setup);

}  // namespace mssph
