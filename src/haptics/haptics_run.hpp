#pragma once
// The haptics of one run as the simulation driver and the command line see them: the session,
// its /haptics log, an optional recording of the device, and the start-up gain check. The
// recording is written only when the run completes (io/output_file.hpp); until then its ticks
// live in the checkpoints, and the log holds the same poses (/haptics/device/...).
#include "config/scene.hpp"
#include "haptics/device_recorder.hpp"
#include "haptics/haptic_log.hpp"
#include "haptics/haptic_metrics.hpp"
#include "haptics/haptics_session.hpp"
#include "io/run_log.hpp"
#include "model/particle_setup.hpp"

#include <string>
#include <vector>

namespace mssph {

class Backend;

// The proxy's index and mass properties in `setup`; the scene must have a proxy.
ProxyModel proxy_model_of(const Scene& scene, const ParticleSetup& setup);

// Warnings of the coupling gains against the explicit stability bound (coupling_stability.hpp);
// none for a scene without a proxy.
std::vector<std::string> haptic_warnings(const Scene& scene, const ParticleSetup& setup);

// Throws InputError when --record-device cannot be honoured: no proxy, or an unknown format.
void check_device_recording_request(const Scene& scene, const std::string& path);

class HapticsRun {
 public:
  // `record_device`: where to write the device trajectory when the run completes ("" for
  // nowhere); `replace`: whether it may replace an existing file there (--force).
  HapticsRun(const Scene& scene, const ParticleSetup& setup, RunLog& log, std::string record_device, bool replace);
  HapticsRun(const HapticsRun&) = delete;  // the session holds pointers to the sinks below
  HapticsRun& operator=(const HapticsRun&) = delete;

  void before_step(Backend& backend, std::size_t step) { session_.before_step(backend, step); }
  // After the last of `steps` steps: the final tick, the summary attributes and the recording. A
  // recording that cannot be written leaves the run completed: recording_error() says why, and so
  // does the log's root attribute `record_device_error`.
  void finish(Backend& backend, std::size_t steps, double wall_seconds);
  // After a failure: the summary of the ticks that ran. Never throws, so that the failure being
  // reported is the one that ended the run.
  void finish_failed(std::size_t steps, double wall_seconds) noexcept;

  double peak_rendered_force() const { return metrics_.peak_rendered_force; }
  // Why the recording of a completed run was not written and what that loses; "" when it was
  // written or none was asked for.
  const std::string& recording_error() const { return recording_error_; }

  // Checkpoints: the session, the run's figures and the recording so far.
  StateArrays save_state() const;
  void restore_state(const StateArrays& state);

 private:
  void write_summary(std::size_t steps, double wall_seconds);
  void write_recording();

  RunLog& run_log_;
  HapticsSession session_;
  HapticLog log_;
  HapticMetrics metrics_;
  DeviceRecorder recorder_;
  std::string record_device_;
  bool replace_recording_ = false;
  std::string recording_error_;
  double dt_;
};

}  // namespace mssph
