#pragma once
// Run-level figures of the haptic loop, accumulated tick by tick: what the summary attributes of
// /haptics report.
#include "backend/state_arrays.hpp"
#include "haptics/haptic_sample.hpp"

#include <cstddef>

namespace mssph {

class HapticMetrics final : public HapticSink {
 public:
  void record(const HapticSample& sample) override;
  // Checkpoints: the figures so far.
  StateArrays save_state() const;
  void restore_state(const StateArrays& state);

  std::size_t ticks = 0;
  std::size_t saturated_ticks = 0;  // any of force clamp, torque clamp, workspace stop
  std::size_t force_saturated_ticks = 0;
  std::size_t torque_saturated_ticks = 0;
  std::size_t workspace_limited_ticks = 0;
  double peak_rendered_force = 0.0;   // [N]
  double peak_rendered_torque = 0.0;  // [N m]
  double max_force_jump = 0.0;        // [N]
  double energy_balance = 0.0;        // injected energy at the last tick [J]; <= 0 for a passive coupling
  double max_injected_energy = 0.0;   // [J]
};

}  // namespace mssph
