#pragma once
// How the coupling sees the proxy at a haptic tick that falls between two simulation states
// (docs/model.md, multi-rate):
//   hold:       the latest simulated state, unchanged;
//   linearised: a local model about the latest state: the proxy moves as a free rigid body under
//               its SPH interaction wrench frozen at that state, gravity, and the coupling wrench
//               in effect, integrated from tick to tick. The next simulation state replaces it.
#include "config/haptics_config.hpp"
#include "util/pose.hpp"

#include <cstddef>

namespace mssph {

struct BodyState;

// The proxy as the haptic loop sees it (scene frame, about its centre of mass).
struct ProxyState {
  double time = 0.0;  // [s]
  Pose pose;
  Twist twist;
  Wrench interaction;  // SPH interaction wrench (paper eq. 8, 9 without the device term)
};

ProxyState proxy_state_of(const BodyState& state, double time);

// Mass properties of the proxy, for the local model and the stability check.
struct ProxyModel {
  std::size_t body = 0;                                        // index of the proxy among the backend's bodies
  double mass = 0.0;                                           // [kg]
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Identity();  // about the centre of mass, body frame [kg m^2]
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();           // [m/s^2]
};

class ProxyPredictor {
 public:
  ProxyPredictor(BetweenSteps mode, const ProxyModel& model) : mode_(mode), model_(model) {}

  // A fresh state from the simulation.
  void reset(const ProxyState& simulated) { state_ = simulated; }
  // The proxy at time t (not before the latest state), `coupling` being the wrench applied to it
  // since the previous call.
  const ProxyState& at(double t, const Wrench& coupling);

 private:
  BetweenSteps mode_;
  ProxyModel model_;
  ProxyState state_;
};

}  // namespace mssph
