#pragma once
// The haptic loop of a run (paper section 4.1, docs/model.md): a device handle, moved by
// the trajectory source, coupled to the proxy through the virtual coupling at the haptic rate,
// while the simulation advances at its own step.
//
// Multi-rate, deterministic in simulated time: tick n happens at n / haptic_rate_hz. Before the
// simulation step [t, t + dt), the session runs every tick in that interval, in order, against
// the proxy state at t (held, or predicted between steps; see proxy_predictor.hpp), and sets the
// proxy's external wrench for the step to the time average over [t, t + dt) of the coupling
// wrench held from tick to tick. When ticks fall on step boundaries (dt = 2.5e-4 s at 1 kHz:
// four steps per tick) that average is exactly the latest tick's wrench; when dt is longer than
// the haptic period it is the impulse of all ticks in the step spread over it. The backend is
// asked for the proxy's state at most once per step that holds a tick, so never more often than
// once per tick.
#include "backend/state_arrays.hpp"
#include "config/haptics_config.hpp"
#include "haptics/device_model.hpp"
#include "haptics/haptic_sample.hpp"
#include "haptics/pose_track.hpp"
#include "haptics/proxy_predictor.hpp"
#include "haptics/workspace_transform.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace mssph {

class Backend;

class HapticsSession {
 public:
  HapticsSession(const HapticsConfig& config, const ProxyModel& proxy, double dt);

  // Every tick is handed to each sink, in the order added; sinks must outlive the session.
  void add_sink(HapticSink& sink) { sinks_.push_back(&sink); }

  // Runs the ticks of simulation step `step` (from step * dt) and sets the proxy's coupling
  // wrench for it. Call right before that step.
  void before_step(Backend& backend, std::size_t step);
  // After the last of `steps` steps: the tick at the end time, if one falls there.
  void finish(Backend& backend, std::size_t steps);

  // Checkpoints (haptics_session_state.cpp): everything the next tick reads that earlier ticks
  // wrote. The proxy predictor is not part of it: every step that holds a tick resets it from the
  // simulation before using it.
  StateArrays save_state() const;
  void restore_state(const StateArrays& state);

  std::size_t ticks() const { return next_tick_; }
  std::size_t state_queries() const { return state_queries_; }
  double period() const { return period_; }

 private:
  double tick_time(std::size_t n) const { return static_cast<double>(n) * period_; }
  ProxyState query_proxy(Backend& backend, double time);
  void start(const ProxyState& proxy);
  // The workspace and the trajectory's track, fixed at the first tick (`origin`: the proxy's
  // starting position, the workspace offset when the scene gives none).
  void set_up_frames(const Eigen::Vector3d& origin);
  void advance_device(double t);
  void tick(double t, const ProxyState& proxy);
  void apply(Backend& backend, const Wrench& wrench);

  HapticsConfig config_;
  ProxyModel proxy_;
  double dt_;
  double period_;
  double time_tolerance_;  // tick and step times closer than this coincide [s]
  DeviceModel device_;
  ProxyPredictor predictor_;
  std::optional<WorkspaceTransform> workspace_;       // fixed at the first tick (its offset may be the proxy's start)
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // the proxy's position at the first tick
  std::optional<PoseTrack> track_;                    // scripted: the hand's target; recorded: the handle itself
  std::vector<HapticSink*> sinks_;

  std::size_t next_tick_ = 0;
  std::size_t state_queries_ = 0;
  DeviceState device_state_;
  Wrench coupling_;  // latest tick's, on the proxy (scene frame)
  Wrench hand_;      // latest tick's, on the handle (device frame)
  RenderedWrench rendered_;
  bool workspace_limited_ = false;
  std::optional<Wrench> applied_;  // last wrench given to the backend
  Pose last_proxy_pose_;           // at the previous tick, for the energy balance
  Pose last_handle_pose_;          // scene frame
  double injected_energy_ = 0.0;
};

}  // namespace mssph
