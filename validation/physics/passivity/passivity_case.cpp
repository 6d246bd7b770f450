// Physics case: passivity of the coupling over a scripted trajectory (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/coupling/coupling_measurements.hpp"

namespace mssph::validation {

CaseResult run_passivity_case(const CaseContext&) {
  CaseResult result;
  result.resolution =
      "dt = 0.25 ms, haptic loop 1 kHz, 5 s script; default gains Kt 1000 N/m, Bt 10 N s/m, Kr 10 N m/rad, "
      "Br 0.1 N m s/rad";
  const PassivityMeasurement m = passivity_over_script({1000.0, 10.0, 10.0, 0.1});
  // Passive: the injected energy never rises above 0 (no tolerance: a passive coupling stores
  // and dissipates only). And the script must exercise it: the taps reach the floor.
  result.checks.push_back(bound_check("max injected energy over 5 s", "J", m.max_injected, 0.0));
  result.checks.push_back(bound_check("final injected energy (dissipated: < -0.1 J)", "J", m.final_injected, -0.1));
  result.checks.push_back(
      range_check("deepest proxy z (the taps reach the floor at -0.05)", "m", -1.0, -0.05, m.deepest));
  for (Check& c : result.checks) c.backend = "rigid-body stand-in";
  result.series.push_back({"injected_energy", "time [s]", m.time, {{"injected energy [J]", m.injected}}});
  return result;
}

}  // namespace mssph::validation
