#include "haptics/haptic_metrics.hpp"

#include <algorithm>

namespace mssph {

void HapticMetrics::record(const HapticSample& s) {
  ++ticks;
  force_saturated_ticks += s.force_saturated ? 1 : 0;
  torque_saturated_ticks += s.torque_saturated ? 1 : 0;
  workspace_limited_ticks += s.workspace_limited ? 1 : 0;
  saturated_ticks += (s.force_saturated || s.torque_saturated || s.workspace_limited) ? 1 : 0;
  peak_rendered_force = std::max(peak_rendered_force, s.rendered.force.norm());
  peak_rendered_torque = std::max(peak_rendered_torque, s.rendered.torque.norm());
  max_force_jump = std::max(max_force_jump, s.force_jump);
  energy_balance = s.injected_energy;
  max_injected_energy = std::max(max_injected_energy, s.injected_energy);
}

// The counts, then the figures in declaration order.
StateArrays HapticMetrics::save_state() const {
  StateArrays state;
  state.put("ticks",
            std::vector<std::int64_t>{static_cast<std::int64_t>(ticks), static_cast<std::int64_t>(saturated_ticks),
                                      static_cast<std::int64_t>(force_saturated_ticks),
                                      static_cast<std::int64_t>(torque_saturated_ticks),
                                      static_cast<std::int64_t>(workspace_limited_ticks)});
  state.put("figures", std::vector<double>{peak_rendered_force, peak_rendered_torque, max_force_jump, energy_balance,
                                           max_injected_energy});
  return state;
}

void HapticMetrics::restore_state(const StateArrays& state) {
  const std::vector<std::int64_t>& counts = state.get<std::int64_t>("ticks", 5);
  ticks = static_cast<std::size_t>(counts[0]);
  saturated_ticks = static_cast<std::size_t>(counts[1]);
  force_saturated_ticks = static_cast<std::size_t>(counts[2]);
  torque_saturated_ticks = static_cast<std::size_t>(counts[3]);
  workspace_limited_ticks = static_cast<std::size_t>(counts[4]);
  const std::vector<double>& figures = state.get<double>("figures", 5);
  peak_rendered_force = figures[0];
  peak_rendered_torque = figures[1];
  max_force_jump = figures[2];
  energy_balance = figures[3];
  max_injected_energy = figures[4];
}

}  // namespace mssph
