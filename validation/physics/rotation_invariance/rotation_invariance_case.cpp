// Physics case: elastic rotation invariance (README.md beside this file). Reference backend:
// R_i and the elastic forces are compared at float64 rounding.
#include "framework/case_functions.hpp"
#include "physics/elastic_statics.hpp"

namespace mssph::validation {

CaseResult run_rotation_invariance_case(const CaseContext&) {
  CaseResult result;
  result.resolution = "dx = 1 cm, h = 2 dx, 8 x 6 x 5 particles, 12 rotations";
  for (const auto& [jitter, correction] : {std::pair{false, false}, std::pair{true, true}}) {
    const RigidMotionResiduals r = rigid_motion_residuals(jitter, correction);
    const std::string tag = jitter ? " (jittered lattice, correction on)" : " (lattice, no correction)";
    // Rounding of exact rotations (~1e-16 relative) gives R_i = Q to ~1e-15 and strains ~1e-15:
    // 1e-12 on R and 1e-9 E h^2 on forces catch any real strain (1e-9 gives ~1e-9 E h^2).
    result.checks.push_back(bound_check("max |R_i - Q|" + tag, "-", r.worst_rotation, 1e-12));
    result.checks.push_back(bound_check("max |f_i| / (E h^2)" + tag, "-", r.worst_force, 1e-9));
  }
  for (Check& c : result.checks) c.backend = "reference";
  return result;
}

}  // namespace mssph::validation
