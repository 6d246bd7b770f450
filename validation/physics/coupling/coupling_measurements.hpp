#pragma once
// The virtual coupling (Colgate et al. 1995; paper 4.1) measured alone, on a rigid-body stand-in
// for the proxy (rigid_body_double.hpp): step responses against the damped oscillator, and
// passivity over a scripted interaction. Shared by the physics cases and tests/haptics.
#include "config/haptics_config.hpp"

#include <vector>

namespace mssph::validation {

// A free proxy pulled by the coupling towards a device held still at a step away: a damped
// oscillator of natural frequency 20 rad/s and damping ratio zeta = 0.3, 2 s at dt = 0.25 ms with
// a 1 kHz haptic loop. Its peak overshoot, as a fraction of the step, lies between
// exp(-pi zeta / sqrt(1 - zeta^2)) (continuous coupling) and the same with the damping ratio
// lowered by the wrench's zero-order hold over a haptic period T, (B - K T / 2) / (2 sqrt(K m))
// (Colgate et al. 1995).
// A device held still at `pose`: a one-sample recording (the handle does not move).
HapticsConfig held_device(const Pose& pose, const SpringDamperGains& gains);

struct StepResponse {
  double overshoot = 0.0;
  double predicted_low = 0.0;          // continuous coupling
  double predicted_high = 0.0;         // with the half-period hold
  double final_error = 0.0;            // |final - target| / step
  double off_axis = 0.0;               // translation: |y| at the end [m]
  std::vector<double> time, response;  // position along the step [m] or angle about the axis [rad]
};
StepResponse translation_step_response();  // 5 cm along x, proxy 1 kg
StepResponse rotation_step_response();     // 0.5 rad about (1, 1, 0), proxy 1e-3 kg m^2

// Five seconds of a hand moving the handle (reaching, tapping a penalty floor 5 cm below the
// start, twisting), with the given coupling gains, proxy 1 kg and 1e-2 kg m^2. The passivity
// observer (Hannaford and Ryu 2002) sums the energy the coupling injects; a passive coupling
// keeps it <= 0 at every tick. `stop_above` ends the run once it exceeds that energy [J].
struct PassivityMeasurement {
  std::size_t ticks = 0;
  double max_injected = 0.0;    // [J]
  double final_injected = 0.0;  // [J]
  double deepest = 0.0;         // lowest proxy z [m]
  double peak_force = 0.0;      // largest upward interaction force [N]
  double end_time = 0.0;        // [s]
  std::vector<double> time, injected;
};
HapticsConfig five_second_script(const SpringDamperGains& coupling);
PassivityMeasurement passivity_over_script(const SpringDamperGains& coupling, double stop_above = 1e300);

}  // namespace mssph::validation
