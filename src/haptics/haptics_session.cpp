#include "haptics/haptics_session.hpp"

#include "backend/backend.hpp"
#include "haptics/virtual_coupling.hpp"

#include <algorithm>

namespace mssph {
namespace {

Wrench operator+(const Wrench& a, const Wrench& b) { return {a.force + b.force, a.torque + b.torque}; }
Wrench operator*(double s, const Wrench& w) { return {s * w.force, s * w.torque}; }
bool operator==(const Wrench& a, const Wrench& b) { return a.force == b.force && a.torque == b.torque; }

// Rotation from `from` to `to`, as a world-frame rotation vector.
Eigen::Vector3d turn(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to) {
  return rotation_vector(to * from.conjugate());
}

}  // namespace

HapticsSession::HapticsSession(const HapticsConfig& config, const ProxyModel& proxy, double dt)
    : config_(config),
      proxy_(proxy),
      dt_(dt),
      period_(1.0 / config.haptic_rate_hz),
      // Far below either period, far above the rounding of n * period against k * dt.
      time_tolerance_(1e-9 * std::min(dt, 1.0 / config.haptic_rate_hz)),
      device_(config.device),
      predictor_(config.between_steps, proxy) {}

ProxyState HapticsSession::query_proxy(Backend& backend, double time) {
  ++state_queries_;
  return proxy_state_of(backend.rigid_body_state(proxy_.body), time);
}

void HapticsSession::before_step(Backend& backend, std::size_t step) {
  const double start = static_cast<double>(step) * dt_;
  const double end = start + dt_;
  // The coupling wrench is piecewise constant, held from tick to tick; `impulse` collects its
  // integral over the step from `held_since` on.
  Wrench impulse;
  double held_since = start;
  bool queried = false;
  while (tick_time(next_tick_) < end - time_tolerance_) {
    const double t = tick_time(next_tick_);
    const double from = std::max(t, start);  // a tick within the tolerance before the step counts as at its start
    if (!queried) {
      predictor_.reset(query_proxy(backend, start));
      queried = true;
    }
    impulse = impulse + (from - held_since) * coupling_;
    const Wrench in_effect = coupling_;
    tick(t, predictor_.at(t, in_effect));
    held_since = from;
  }
  // One wrench over the whole step (no tick inside, or one at its start) is applied as it is.
  const bool one_piece = held_since - start <= time_tolerance_;
  apply(backend, one_piece ? coupling_ : (1.0 / dt_) * (impulse + (end - held_since) * coupling_));
}

void HapticsSession::finish(Backend& backend, std::size_t steps) {
  const double end = static_cast<double>(steps) * dt_;
  bool queried = false;
  while (tick_time(next_tick_) <= end + time_tolerance_) {
    const double t = tick_time(next_tick_);
    if (!queried) {
      predictor_.reset(query_proxy(backend, end));
      queried = true;
    }
    const Wrench in_effect = coupling_;
    tick(t, predictor_.at(t, in_effect));
  }
}

void HapticsSession::set_up_frames(const Eigen::Vector3d& origin) {
  origin_ = origin;
  const WorkspaceConfig& w = config_.device.workspace;
  workspace_.emplace(w.scale, w.offset.value_or(origin), w.rotation);
  const TrajectoryConfig& trajectory = config_.trajectory;
  switch (trajectory.source) {
    case TrajectorySource::free:
      break;
    case TrajectorySource::scripted: {
      std::vector<double> times;
      std::vector<Pose> poses;
      for (const Keyframe& k : trajectory.keyframes) {
        times.push_back(k.time);
        poses.push_back(k.pose);
      }
      track_.emplace(std::move(times), std::move(poses));
      break;
    }
    case TrajectorySource::recorded: {
      // Recorded time counts from the first sample.
      std::vector<double> times = trajectory.recording.time;
      const double first = times.front();
      for (double& t : times) t -= first;
      track_.emplace(std::move(times), trajectory.recording.pose);
      break;
    }
  }
}

void HapticsSession::start(const ProxyState& proxy) {
  set_up_frames(proxy.pose.position);
  switch (config_.trajectory.source) {
    case TrajectorySource::free:
      // The handle starts where the proxy is, moving with it: no initial coupling force.
      device_state_ = DeviceState{workspace_->to_device(proxy.pose), workspace_->to_device(proxy.twist)};
      break;
    case TrajectorySource::scripted:
      device_state_ = DeviceState{track_->at(0.0).pose, Twist{}};  // held at rest at the first target
      break;
    case TrajectorySource::recorded: {
      const PoseTrack::Sample sample = track_->at(0.0);
      device_state_ = DeviceState{sample.pose, sample.twist};
      break;
    }
  }
}

void HapticsSession::advance_device(double t) {
  if (config_.trajectory.source == TrajectorySource::recorded) {
    const PoseTrack::Sample sample = track_->at(t);
    device_state_ = DeviceState{sample.pose, sample.twist};
    workspace_limited_ = false;  // recorded poses were checked against the workspace
    return;
  }
  workspace_limited_ = device_.advance(device_state_, rendered_.wrench + hand_, period_);
}

void HapticsSession::tick(double t, const ProxyState& proxy) {
  const bool first = next_tick_ == 0;
  if (first) {
    start(proxy);
  } else {
    advance_device(t);
  }
  const Pose handle = workspace_->to_scene(device_state_.pose);
  const Twist handle_twist = workspace_->to_scene(device_state_.twist);

  // Passivity observer (Hannaford and Ryu 2002) on the coupling's two ports: the work its held
  // wrench did since the last tick on the proxy (+F, +tau) and on the handle (-F, -tau). A
  // passive coupling never has a positive total; the sampled spring of a coupling with too
  // little damping (Colgate et al. 1995: B < K T / 2) makes it grow.
  if (!first) {
    injected_energy_ += coupling_.force.dot((proxy.pose.position - last_proxy_pose_.position) -
                                            (handle.position - last_handle_pose_.position)) +
                        coupling_.torque.dot(turn(last_proxy_pose_.orientation, proxy.pose.orientation) -
                                             turn(last_handle_pose_.orientation, handle.orientation));
  }
  last_proxy_pose_ = proxy.pose;
  last_handle_pose_ = handle;

  coupling_ = spring_damper_wrench(config_.coupling, handle, handle_twist, proxy.pose, proxy.twist);
  const Eigen::Vector3d previous_force = rendered_.wrench.force;
  rendered_ = device_.render(coupling_, *workspace_);
  if (config_.trajectory.source == TrajectorySource::scripted) {
    const PoseTrack::Sample target = track_->at(t);
    hand_ = spring_damper_wrench(config_.trajectory.hand, target.pose, target.twist, device_state_.pose,
                                 device_state_.twist);
  }

  HapticSample sample;
  sample.time = t;
  sample.device_pose = device_state_.pose;
  sample.device_twist = device_state_.twist;
  sample.proxy_pose = proxy.pose;
  sample.proxy_twist = proxy.twist;
  sample.interaction = proxy.interaction;
  sample.coupling = coupling_;
  sample.rendered = rendered_.wrench;
  sample.force_saturated = rendered_.force_saturated;
  sample.torque_saturated = rendered_.torque_saturated;
  sample.workspace_limited = workspace_limited_;
  sample.force_jump = first ? 0.0 : (rendered_.wrench.force - previous_force).norm();
  sample.injected_energy = injected_energy_;
  for (HapticSink* sink : sinks_) sink->record(sample);
  ++next_tick_;
}

void HapticsSession::apply(Backend& backend, const Wrench& wrench) {
  if (applied_ && *applied_ == wrench) return;  // a GPU backend would copy it for nothing
  backend.set_external_wrench(proxy_.body, wrench.force, wrench.torque);
  applied_ = wrench;
}

}  // namespace mssph
