#pragma once
// The /haptics group of the run log: one row per haptic tick (units in each dataset's `units`
// attribute) and, at the end, summary attributes whose names carry their units.
#include "haptics/haptic_metrics.hpp"
#include "haptics/haptic_sample.hpp"
#include "io/run_log.hpp"

#include <cstddef>

namespace mssph {

// Counts and times of the run the summary divides by.
struct HapticRunTotals {
  std::size_t steps = 0;
  std::size_t state_queries = 0;  // Backend::rigid_body_state calls
  double simulated_seconds = 0.0;
  double wall_seconds = 0.0;
};

class HapticLog final : public HapticSink {
 public:
  explicit HapticLog(RunLog& log);
  void record(const HapticSample& sample) override;
  void write_summary(const HapticMetrics& metrics, const HapticRunTotals& totals);

 private:
  RunLog& log_;
  std::size_t time_;
  std::size_t device_position_, device_orientation_, device_linear_velocity_, device_angular_velocity_;
  std::size_t proxy_position_, proxy_orientation_, proxy_linear_velocity_, proxy_angular_velocity_;
  std::size_t interaction_force_, interaction_torque_;
  std::size_t coupling_force_, coupling_torque_;
  std::size_t rendered_force_, rendered_torque_;
  std::size_t saturation_, force_jump_, injected_energy_;
};

}  // namespace mssph
