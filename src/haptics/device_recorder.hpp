#pragma once
// Collects the handle's pose at every tick, to write it as a device recording that a later run
// can replay (`mssph run --record-device FILE`, then trajectory source "recorded").
#include "backend/state_arrays.hpp"
#include "config/device_recording.hpp"
#include "haptics/haptic_sample.hpp"
#include "util/pose_packing.hpp"

namespace mssph {

class DeviceRecorder final : public HapticSink {
 public:
  void record(const HapticSample& sample) override {
    recording_.time.push_back(sample.time);
    recording_.pose.push_back(sample.device_pose);
  }
  const DeviceRecording& recording() const { return recording_; }

  // Checkpoints: the recording so far (times, then 7 pose values per tick).
  StateArrays save_state() const {
    PosePacker poses;
    for (const Pose& p : recording_.pose) poses.add(p);
    StateArrays state;
    state.put("time", recording_.time);
    state.put("pose", poses.take());
    return state;
  }
  void restore_state(const StateArrays& state) {
    recording_.time = state.get<double>("time");
    PoseUnpacker poses(state.get<double>("pose", 7 * recording_.time.size()));
    recording_.pose.clear();
    for (std::size_t k = 0; k < recording_.time.size(); ++k) recording_.pose.push_back(poses.pose());
  }

 private:
  DeviceRecording recording_;
};

}  // namespace mssph
