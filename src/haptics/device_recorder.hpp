#pragma once
// Collects the handle's pose at every tick, to write it as a device recording that a later run
// can replay (`mssph run --record-device FILE`, then trajectory source "recorded").
#include "config/device_recording.hpp"
#include "haptics/haptic_sample.hpp"

namespace mssph {

class DeviceRecorder final : public HapticSink {
 public:
  void record(const HapticSample& sample) override {
    recording_.time.push_back(sample.time);
    recording_.pose.push_back(sample.device_pose);
  }
  const DeviceRecording& recording() const { return recording_; }

 private:
  DeviceRecording recording_;
};

}  // namespace mssph
