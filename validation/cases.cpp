// The registry of validation cases, in the order they run. A new case: a folder with its
// scene, README and measuring code, its function declared in framework/case_functions.hpp, and
// one line here (see README.md).
#include "framework/case_functions.hpp"

namespace mssph::validation {

const std::vector<ValidationCase>& all_cases() {
  static const std::vector<ValidationCase> cases{
      {"kernels", "one_step", "kernels/one_step", "one force evaluation, float32 backends vs float64 reference",
       run_one_step_case},
      {"kernels", "sphere_drops", "kernels/sphere_drops", "Figure 3 sphere drops over 0.5 s, float32 vs reference",
       run_sphere_drops_case},
      {"physics", "hydrostatic", "physics/hydrostatic", "slope of pressure against depth in a settled column vs rho0 g",
       run_hydrostatic_case},
      {"physics", "archimedes", "physics/archimedes", "floating depth of spheres of density 500 and 700 in water",
       run_archimedes_case},
      {"selftest", "wrong_expectation", "selftest/wrong_expectation",
       "a flat-punch force curve judged against Hertz: must FAIL", run_wrong_expectation_case},
  };
  return cases;
}

}  // namespace mssph::validation
