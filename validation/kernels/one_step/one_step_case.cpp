// The kernels suite's one-step case: every fast backend against the reference on each one-step
// scene, per quantity. The seed is the run's fresh seed (printed by `mssph validate`).
#include "framework/case_functions.hpp"
#include "one_step.hpp"

#include <chrono>
#include <iostream>

namespace mssph::validation {

CaseResult run_one_step_case(const CaseContext& context) {
  CaseResult result;
  result.resolution =
      "dx = 0.02 m, h = 0.04 m, lattice jitter 0.15 dx; deformable particles stretched 1 %, rotated "
      "and shaken by 0.02 dx";
  result.details = "seed " + std::to_string(context.seed) +
                   " (replay the unit test with MSSPH_TEST_SEED=" + std::to_string(context.seed) + ")";
  for (const std::string& backend : context.fast_backends) {
    const std::string skip = why_backend_cannot_run(backend);
    for (const std::string& name : one_step_scene_names()) {
      const std::string prefix = backend + " " + name + " ";
      if (!skip.empty()) {
        result.checks.push_back(skipped_check(prefix + "one step", skip));
        result.checks.back().backend = backend;
        continue;
      }
      std::cerr << "validate: one step, " << backend << " vs reference, " << name << "\n";
      const OneStepErrors e = one_step_errors(backend, one_step_scene(name), context.seed);
      std::vector<Check> checks{
          bound_check(prefix + "density", "rel. L2", e.density, kOneStepDensityBound),
          bound_check(prefix + "pressure", "rel. L2", e.pressure, kOneStepDensityBound),
          bound_check(prefix + "pressure force", "rel. L2", e.pressure_force, kOneStepForceBound),
          bound_check(prefix + "viscosity force", "rel. L2", e.viscosity_force, kOneStepForceBound),
          bound_check(prefix + "total force", "rel. L2", e.total_force, kOneStepForceBound)};
      if (e.deformed) {
        checks.push_back(bound_check(prefix + "elastic force", "rel. L2", e.elastic_force, kOneStepForceBound));
        checks.push_back(bound_check(prefix + "rotation", "rel. L2", e.rotation, kOneStepRotationBound));
      }
      for (Check& c : checks) {
        c.backend = backend;
        result.checks.push_back(std::move(c));
      }
    }
  }
  return result;
}

}  // namespace mssph::validation
