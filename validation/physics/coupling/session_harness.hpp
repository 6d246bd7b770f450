#pragma once
// Runs a HapticsSession against the rigid-body double the way the simulation driver does
// (before_step, step, ..., finish) and keeps every sample.
#include "haptics/haptics_session.hpp"
#include "physics/coupling/rigid_body_double.hpp"

#include <cmath>
#include <functional>
#include <vector>

namespace mssph::test {

class SampleSink final : public HapticSink {
 public:
  void record(const HapticSample& sample) override { samples.push_back(sample); }
  std::vector<HapticSample> samples;
};

inline ProxyModel proxy_model(double mass, double inertia, const Eigen::Vector3d& gravity = Eigen::Vector3d::Zero()) {
  return ProxyModel{0, mass, inertia * Eigen::Matrix3d::Identity(), gravity};
}

// Steps to `duration`; `stop` (optional) ends the run early once it returns true for the latest
// sample. Returns every sample.
inline std::vector<HapticSample> run_session(const HapticsConfig& config, RigidBodyDouble& body, double mass,
                                             double inertia, double dt, double duration,
                                             const std::function<bool(const HapticSample&)>& stop = {}) {
  HapticsSession session(config, proxy_model(mass, inertia, body.gravity), dt);
  SampleSink sink;
  session.add_sink(sink);
  const auto steps = static_cast<std::size_t>(std::llround(duration / dt));
  std::size_t done = 0;
  for (; done < steps; ++done) {
    if (stop && !sink.samples.empty() && stop(sink.samples.back())) return sink.samples;
    session.before_step(body, done);
    body.step();
  }
  session.finish(body, done);
  return sink.samples;
}

}  // namespace mssph::test
