// Physics case: torque-free spin keeps its angular momentum (README.md beside this file).
#include "framework/case_functions.hpp"
#include "torque_free_spin.hpp"

namespace mssph::validation {

CaseResult run_torque_free_spin_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "angular momentum")) return *skipped;
  // 288 particles: the same in --quick and full.
  const SpinMeasurement m = measure_torque_free_spin(context.physics_backend, case_scene("physics/torque_free_spin"));
  const bool float64 = context.physics_backend == "reference";
  result.resolution = "dx = 1 cm (12 x 6 x 3 particles), dt = 0.25 ms, 8000 steps (2 s)";
  result.checks = {
      // float64: the integrator advances L itself, so it holds to rounding. float32: L is summed
      // from particle velocities in single precision each step: 1e-5 is ~100 float epsilons.
      bound_check("max |L - L0| / |L0|", "-", m.worst_momentum_error, float64 ? 1e-12 : 1e-5),
      // The orientation update exp(omega dt) is first order: O(|omega| dt) = 1.3e-3 per tumble.
      bound_check("max |E - E0| / E0", "-", m.worst_energy_drift, 5e-3),
      // It must tumble for the test to mean anything.
      range_check("body-axis omega turned (it tumbled)", "deg", 90.0, 180.0, m.largest_turn_degrees),
      bound_check("|p| at the end (nothing pushed it)", "kg m/s", m.final_linear_momentum, float64 ? 1e-12 : 1e-6)};
  for (Check& c : result.checks) c.backend = context.physics_backend;
  result.series.push_back(
      {"conservation", "time [s]", m.time, {{"|L - L0| / |L0|", m.momentum_error}, {"|E - E0| / E0", m.energy_drift}}});
  return result;
}

}  // namespace mssph::validation
