#pragma once
// Many steps: a float32 backend against the reference on paper Figure 3's sphere drops
// (configs/sphere_drop_{rigid,deformable,fluid}.json): the proxy sphere's interaction force curve
// and path over 0.5 s. Shared by the kernels suite and tests/backends/backend_agreement_test.cpp.
#include "model/particle_setup.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mssph::validation {

// A shipped scene (configs/<config>) at the given spacing, cut to `duration` seconds, with
// further --set overrides.
ParticleSetup shipped_scene(const std::string& config, double spacing, double duration,
                            const std::vector<std::string>& extra = {});

struct DropAgreement {
  double force_error = 0.0;  // NRMS of the interaction force, over the reference's peak force
  double path_error = 0.0;   // NRMS of the displacement, over the farthest the reference travels
  double travel = 0.0;       // that farthest displacement [m]
  std::vector<double> time;  // [s]
  std::vector<double> force_reference, force_candidate;  // z component of the interaction force [N]
};

// Runs `steps` steps of the setup on the reference and on `backend`, tracking body `proxy`.
DropAgreement drop_agreement(const std::string& backend, const ParticleSetup& setup, std::size_t proxy,
                             std::size_t steps);

// Bounds (set before measuring, as in the unit test): 2 % NRMS for the rigid and deformable
// drops; 5 % for the fluid drop, as splashing fluid is chaotic and float32 rounding grows into
// visible differences.
double drop_tolerance(const std::string& config);

}  // namespace mssph::validation
