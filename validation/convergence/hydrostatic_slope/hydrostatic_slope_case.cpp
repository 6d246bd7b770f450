// Convergence case: the hydrostatic slope dP/dz at three spacings (README.md beside this file).
#include "framework/case_functions.hpp"
#include "framework/convergence.hpp"
#include "physics/fluids.hpp"

namespace mssph::validation {

CaseResult run_hydrostatic_convergence_case(const CaseContext& context) {
  if (auto skipped = skipped_without_physics_backend(context, "dP/dz convergence")) return *skipped;
  // Quick: 6, 8 and 10 particles across the 20 cm tank; coarser spacings leave fewer than 3
  // interior slabs between h above the floor and 2 h below the surface (README.md).
  const std::vector<double> spacing =
      context.quick ? std::vector<double>{0.2 / 6.0, 0.025, 0.02} : std::vector<double>{0.02, 0.2 / 14.0, 0.01};
  const Scene base = case_scene("physics/hydrostatic");
  std::vector<double> expected, measured;
  for (double dx : spacing) {
    const HydrostaticMeasurement m =
        measure_hydrostatic(context.physics_backend, case_scene("physics/hydrostatic", resolution_overrides(base, dx)));
    if (m.height.size() < 2) throw std::runtime_error("dx = " + exact(dx) + ": fewer than 2 slabs to fit");
    expected.push_back(m.expected_slope);
    measured.push_back(m.slope);
  }
  // 5 %: the physics case's tolerance.
  CaseResult result = convergence_result("dP/dz", spacing, expected, measured, 0.05, context.physics_backend);
  result.resolution = "the physics/hydrostatic scene at three spacings, dt proportional to dx";
  return result;
}

}  // namespace mssph::validation
