// Physics case: coupling step responses against the damped oscillator (README.md beside this
// file). The proxy is a rigid-body stand-in: the coupling is measured alone.
#include "framework/case_functions.hpp"
#include "physics/coupling/coupling_measurements.hpp"

namespace mssph::validation {

CaseResult run_coupling_step_case(const CaseContext&) {
  CaseResult result;
  result.resolution = "dt = 0.25 ms, haptic loop 1 kHz, 2 s; omega = 20 rad/s, zeta = 0.3";
  for (const bool rotation : {false, true}) {
    const StepResponse r = rotation ? rotation_step_response() : translation_step_response();
    const std::string tag = rotation ? "rotation 0.5 rad: " : "translation 5 cm: ";
    // The overshoot between the continuous prediction and the held one, 1 % either side: the
    // O((omega T)^2) = 4e-4 terms the half-period model leaves out and sampling the peak at ticks.
    result.checks.push_back(
        range_check(tag + "overshoot / step", "-", 0.99 * r.predicted_low, 1.01 * r.predicted_high, r.overshoot));
    // After 2 s the envelope exp(-zeta omega t) is 6e-6 of the step; 1e-4 leaves room for the
    // discrete loop's slightly lower damping.
    result.checks.push_back(bound_check(tag + "|final - target| / step", "-", r.final_error, 1e-4));
    result.series.push_back({rotation ? "rotation_step" : "translation_step",
                             "time [s]",
                             r.time,
                             {{rotation ? "angle about the axis [rad]" : "position along the step [m]", r.response}}});
  }
  for (Check& c : result.checks) c.backend = "rigid-body stand-in";
  return result;
}

}  // namespace mssph::validation
