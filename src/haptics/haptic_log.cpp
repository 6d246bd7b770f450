#include "haptics/haptic_log.hpp"

namespace mssph {
namespace {

const std::vector<std::string> kXyz{"x", "y", "z"};
const std::vector<std::string> kQuaternion{"qx", "qy", "qz", "qw"};

void append3(RunLog& log, std::size_t series, const Eigen::Vector3d& v) {
  const double row[3] = {v.x(), v.y(), v.z()};
  log.append(series, row);
}

void append_quaternion(RunLog& log, std::size_t series, const Eigen::Quaterniond& q) {
  const double row[4] = {q.x(), q.y(), q.z(), q.w()};
  log.append(series, row);
}

void append1(RunLog& log, std::size_t series, double v) { log.append(series, std::span<const double>(&v, 1)); }

}  // namespace

HapticLog::HapticLog(RunLog& log) : log_(log) {
  time_ = log.add_series("/haptics/time", 1, "s", "simulated time of each haptic tick");
  device_position_ = log.add_series("/haptics/device/position", 3, "m", "handle position, device frame", kXyz);
  device_orientation_ =
      log.add_series("/haptics/device/orientation", 4, "1", "handle orientation, device frame", kQuaternion);
  device_linear_velocity_ =
      log.add_series("/haptics/device/linear_velocity", 3, "m/s", "handle velocity, device frame", kXyz);
  device_angular_velocity_ =
      log.add_series("/haptics/device/angular_velocity", 3, "rad/s", "handle angular velocity, device frame", kXyz);
  proxy_position_ = log.add_series("/haptics/proxy/position", 3, "m", "proxy centre of mass, scene frame", kXyz);
  proxy_orientation_ =
      log.add_series("/haptics/proxy/orientation", 4, "1", "proxy orientation, scene frame", kQuaternion);
  proxy_linear_velocity_ =
      log.add_series("/haptics/proxy/linear_velocity", 3, "m/s", "proxy centre-of-mass velocity, scene frame", kXyz);
  proxy_angular_velocity_ =
      log.add_series("/haptics/proxy/angular_velocity", 3, "rad/s", "proxy angular velocity, scene frame", kXyz);
  interaction_force_ = log.add_series("/haptics/interaction/force", 3, "N",
                                      "sum of SPH interaction forces on the proxy's particles (paper eq. 8)", kXyz);
  interaction_torque_ = log.add_series("/haptics/interaction/torque", 3, "N m",
                                       "their torque about the proxy's centre of mass (paper eq. 9)", kXyz);
  coupling_force_ = log.add_series("/haptics/coupling/force", 3, "N",
                                   "virtual coupling force on the proxy, scene frame (Colgate et al. 1995)", kXyz);
  coupling_torque_ =
      log.add_series("/haptics/coupling/torque", 3, "N m", "virtual coupling torque on the proxy, scene frame", kXyz);
  rendered_force_ =
      log.add_series("/haptics/rendered/force", 3, "N",
                     "force the device renders at the handle: -F, device frame, scaled and clamped", kXyz);
  rendered_torque_ = log.add_series("/haptics/rendered/torque", 3, "N m",
                                    "torque the device renders: -tau, device frame, scaled and clamped", kXyz);
  saturation_ = log.add_series("/haptics/saturation", 3, "1",
                               "1 where the rendered force or torque was clamped to the device's limit, or the handle "
                               "met the workspace boundary",
                               {"force", "torque", "workspace"});
  force_jump_ = log.add_series("/haptics/force_jump", 1, "N", "|rendered force - previous tick's rendered force|");
  injected_energy_ = log.add_series("/haptics/injected_energy", 1, "J",
                                    "passivity observer: work of the coupling on proxy and handle so far; a passive "
                                    "coupling keeps it <= 0");
}

void HapticLog::record(const HapticSample& s) {
  append1(log_, time_, s.time);
  append3(log_, device_position_, s.device_pose.position);
  append_quaternion(log_, device_orientation_, s.device_pose.orientation);
  append3(log_, device_linear_velocity_, s.device_twist.linear);
  append3(log_, device_angular_velocity_, s.device_twist.angular);
  append3(log_, proxy_position_, s.proxy_pose.position);
  append_quaternion(log_, proxy_orientation_, s.proxy_pose.orientation);
  append3(log_, proxy_linear_velocity_, s.proxy_twist.linear);
  append3(log_, proxy_angular_velocity_, s.proxy_twist.angular);
  append3(log_, interaction_force_, s.interaction.force);
  append3(log_, interaction_torque_, s.interaction.torque);
  append3(log_, coupling_force_, s.coupling.force);
  append3(log_, coupling_torque_, s.coupling.torque);
  append3(log_, rendered_force_, s.rendered.force);
  append3(log_, rendered_torque_, s.rendered.torque);
  const double flags[3] = {s.force_saturated ? 1.0 : 0.0, s.torque_saturated ? 1.0 : 0.0,
                           s.workspace_limited ? 1.0 : 0.0};
  log_.append(saturation_, flags);
  append1(log_, force_jump_, s.force_jump);
  append1(log_, injected_energy_, s.injected_energy);
}

void HapticLog::write_summary(const HapticMetrics& m, const HapticRunTotals& totals) {
  const auto ratio = [&](std::size_t count) {
    return m.ticks == 0 ? 0.0 : static_cast<double>(count) / static_cast<double>(m.ticks);
  };
  const auto per_wall_second = [&](std::size_t count) {
    return totals.wall_seconds > 0.0 ? static_cast<double>(count) / totals.wall_seconds : 0.0;
  };
  const std::string g = "/haptics";
  log_.set_attribute(g, "ticks", static_cast<long long>(m.ticks));
  log_.set_attribute(g, "proxy_state_queries", static_cast<long long>(totals.state_queries));
  log_.set_attribute(g, "peak_rendered_force_N", m.peak_rendered_force);
  log_.set_attribute(g, "peak_rendered_torque_Nm", m.peak_rendered_torque);
  log_.set_attribute(g, "saturation_ratio", ratio(m.saturated_ticks));
  log_.set_attribute(g, "force_saturation_ratio", ratio(m.force_saturated_ticks));
  log_.set_attribute(g, "torque_saturation_ratio", ratio(m.torque_saturated_ticks));
  log_.set_attribute(g, "workspace_limit_ratio", ratio(m.workspace_limited_ticks));
  log_.set_attribute(g, "max_force_jump_N", m.max_force_jump);
  log_.set_attribute(g, "energy_balance_J", m.energy_balance);
  log_.set_attribute(g, "max_injected_energy_J", m.max_injected_energy);
  // Achieved rates: simulated steps and haptic ticks per wall-clock second of the stepping loop.
  log_.set_attribute(g, "simulation_rate_Hz", per_wall_second(totals.steps));
  log_.set_attribute(g, "haptic_rate_Hz", per_wall_second(m.ticks));
  log_.set_attribute(g, "real_time_factor",
                     totals.simulated_seconds > 0.0 ? totals.wall_seconds / totals.simulated_seconds : 0.0);
}

}  // namespace mssph
