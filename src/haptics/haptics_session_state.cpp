// HapticsSession's checkpoint: the tick counters, the device, the coupling's held wrenches, the
// passivity observer and the frames fixed at the first tick.
#include "haptics/haptics_session.hpp"

#include "util/pose_packing.hpp"

namespace mssph {
namespace {

// Values in the "motion" array, in the order save_state packs them.
constexpr std::size_t kMotionValues = 7 + 6 + 6 + 6 + 6 + 6 + 7 + 7 + 1 + 3;
constexpr std::size_t kFlags = 4;  // force and torque saturated, workspace limited, a wrench applied

}  // namespace

StateArrays HapticsSession::save_state() const {
  StateArrays state;
  state.put_count("next_tick", static_cast<std::int64_t>(next_tick_));
  state.put_count("state_queries", static_cast<std::int64_t>(state_queries_));
  PosePacker motion;
  motion.add(device_state_.pose);
  motion.add(device_state_.twist);
  motion.add(coupling_);
  motion.add(hand_);
  motion.add(rendered_.wrench);
  motion.add(applied_.value_or(Wrench{}));
  motion.add(last_proxy_pose_);
  motion.add(last_handle_pose_);
  motion.add(injected_energy_);
  motion.add(origin_);
  state.put("motion", motion.take());
  state.put("flags", std::vector<std::uint8_t>{rendered_.force_saturated, rendered_.torque_saturated,
                                               workspace_limited_, applied_.has_value()});
  return state;
}

void HapticsSession::restore_state(const StateArrays& state) {
  next_tick_ = static_cast<std::size_t>(state.count("next_tick"));
  state_queries_ = static_cast<std::size_t>(state.count("state_queries"));
  PoseUnpacker motion(state.get<double>("motion", kMotionValues));
  device_state_.pose = motion.pose();
  device_state_.twist = motion.twist();
  coupling_ = motion.wrench();
  hand_ = motion.wrench();
  rendered_.wrench = motion.wrench();
  const Wrench applied = motion.wrench();
  last_proxy_pose_ = motion.pose();
  last_handle_pose_ = motion.pose();
  injected_energy_ = motion.scalar();
  const Eigen::Vector3d origin = motion.vector();
  const std::vector<std::uint8_t>& flags = state.get<std::uint8_t>("flags", kFlags);
  rendered_.force_saturated = flags[0] != 0;
  rendered_.torque_saturated = flags[1] != 0;
  workspace_limited_ = flags[2] != 0;
  applied_.reset();
  if (flags[3] != 0) applied_ = applied;
  workspace_.reset();
  track_.reset();
  if (next_tick_ > 0) set_up_frames(origin);
}

}  // namespace mssph
