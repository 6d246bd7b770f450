#include "haptics/haptics_run.hpp"

#include "haptics/coupling_stability.hpp"
#include "io/output_file.hpp"
#include "util/errors.hpp"

#include <algorithm>

namespace mssph {

ProxyModel proxy_model_of(const Scene& scene, const ParticleSetup& setup) {
  const auto it = std::find_if(setup.bodies.begin(), setup.bodies.end(),
                               [&](const BodySetup& b) { return b.name == scene.proxy->body; });
  ProxyModel model;
  model.body = static_cast<std::size_t>(it - setup.bodies.begin());
  model.mass = it->mass;
  model.inertia_body = it->inertia_body;
  model.gravity = setup.gravity;
  return model;
}

std::vector<std::string> haptic_warnings(const Scene& scene, const ParticleSetup& setup) {
  if (!scene.proxy) return {};
  return coupling_stability_warnings(scene.proxy->haptics, scene.proxy->body, proxy_model_of(scene, setup), setup.dt);
}

void check_device_recording_request(const Scene& scene, const std::string& path) {
  if (!scene.proxy) {
    throw InputError("--record-device " + path + ": scene " + scene.source_file +
                     " has no \"proxy\", so there is no haptic device to record");
  }
  check_recording_path(path);
}

HapticsRun::HapticsRun(const Scene& scene, const ParticleSetup& setup, RunLog& log, std::string record_device,
                       bool replace)
    : run_log_(log),
      session_(scene.proxy->haptics, proxy_model_of(scene, setup), setup.dt),
      log_(log),
      record_device_(std::move(record_device)),
      replace_recording_(replace),
      dt_(setup.dt) {
  session_.add_sink(log_);
  session_.add_sink(metrics_);
  if (!record_device_.empty()) session_.add_sink(recorder_);
  log.set_attribute("/haptics", "proxy_body", scene.proxy->body);
  log.set_attribute("/haptics", "trajectory", std::string(to_string(scene.proxy->haptics.trajectory.source)));
  log.set_attribute("/haptics", "haptic_period_s", session_.period());
}

void HapticsRun::write_summary(std::size_t steps, double wall_seconds) {
  log_.write_summary(metrics_,
                     HapticRunTotals{steps, session_.state_queries(), static_cast<double>(steps) * dt_, wall_seconds});
}

void HapticsRun::write_recording() {
  if (record_device_.empty()) return;
  const DeviceRecording& recording = recorder_.recording();
  const std::string head = "--record-device " + record_device_ + ": the recording of " +
                           std::to_string(recording.time.size()) + " haptic ticks ";
  try {
    OutputFile(record_device_, replace_recording_).write(device_recording_bytes(record_device_, recording));
  } catch (const OutputKeptAside& e) {
    recording_error_ = head + "is whole but not at its name: " + e.what() + "; nothing is lost";
  } catch (const std::exception& e) {
    recording_error_ = head + "was not written (" + e.what() +
                       "); only that file is lost: the simulation completed, and its log holds the same poses, one "
                       "per tick, in /haptics/device/position and /haptics/device/orientation";
  }
  if (!recording_error_.empty()) run_log_.set_attribute("/", "record_device_error", recording_error_);
}

void HapticsRun::finish(Backend& backend, std::size_t steps, double wall_seconds) {
  session_.finish(backend, steps);
  write_summary(steps, wall_seconds);
  write_recording();
}

void HapticsRun::finish_failed(std::size_t steps, double wall_seconds) noexcept {
  try {
    write_summary(steps, wall_seconds);
  } catch (const std::exception&) {
    // The run already failed for a reason the caller reports; its log says so.
  }
}

StateArrays HapticsRun::save_state() const {
  StateArrays state;
  state.add_part("session", session_.save_state());
  state.add_part("metrics", metrics_.save_state());
  if (!record_device_.empty()) state.add_part("recording", recorder_.save_state());
  return state;
}

void HapticsRun::restore_state(const StateArrays& state) {
  session_.restore_state(state.part("session"));
  metrics_.restore_state(state.part("metrics"));
  if (!record_device_.empty()) recorder_.restore_state(state.part("recording"));
}

}  // namespace mssph
