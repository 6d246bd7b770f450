#include "config/haptics_config.hpp"

#include "config/json_reader.hpp"

#include <filesystem>

namespace mssph {
namespace {

SpringDamperGains read_gains(const JsonReader& reader, const SpringDamperGains& defaults) {
  reader.allow_only({"linear_stiffness", "linear_damping", "angular_stiffness", "angular_damping"});
  SpringDamperGains gains;
  gains.linear_stiffness = reader.number_or("linear_stiffness", defaults.linear_stiffness, Interval::non_negative());
  gains.linear_damping = reader.number_or("linear_damping", defaults.linear_damping, Interval::non_negative());
  gains.angular_stiffness = reader.number_or("angular_stiffness", defaults.angular_stiffness, Interval::non_negative());
  gains.angular_damping = reader.number_or("angular_damping", defaults.angular_damping, Interval::non_negative());
  return gains;
}

SpringDamperGains read_gains_or(const JsonReader& parent, const std::string& key, const SpringDamperGains& defaults) {
  const auto section = parent.optional_child(key);
  return section ? read_gains(*section, defaults) : defaults;
}

WorkspaceConfig read_workspace(const JsonReader& reader) {
  reader.allow_only({"scale", "offset", "rotation"});
  WorkspaceConfig workspace;
  workspace.scale = reader.number_or("scale", workspace.scale, Interval::positive());
  if (reader.has("offset")) workspace.offset = reader.vec3("offset");
  workspace.rotation = reader.quaternion_or("rotation", workspace.rotation);
  return workspace;
}

DeviceConfig read_device(const JsonReader& reader) {
  reader.allow_only({"mass", "inertia", "linear_damping", "angular_damping", "max_force", "max_torque",
                     "workspace_radius", "force_scale", "torque_scale", "workspace"});
  DeviceConfig device;
  device.mass = reader.number_or("mass", device.mass, Interval::positive());
  device.inertia = reader.number_or("inertia", device.inertia, Interval::positive());
  device.linear_damping = reader.number_or("linear_damping", device.linear_damping, Interval::non_negative());
  device.angular_damping = reader.number_or("angular_damping", device.angular_damping, Interval::non_negative());
  device.max_force = reader.number_or("max_force", device.max_force, Interval::positive());
  device.max_torque = reader.number_or("max_torque", device.max_torque, Interval::positive());
  device.workspace_radius = reader.number_or("workspace_radius", device.workspace_radius, Interval::positive());
  device.force_scale = reader.number_or("force_scale", device.force_scale, Interval::positive());
  device.torque_scale = reader.number_or("torque_scale", device.torque_scale, Interval::positive());
  if (const auto workspace = reader.optional_child("workspace")) device.workspace = read_workspace(*workspace);
  return device;
}

std::vector<Keyframe> read_keyframes(const JsonReader& reader, const DeviceConfig& device) {
  std::vector<Keyframe> keyframes;
  for (const JsonReader& k : reader.elements()) {
    k.allow_only({"time", "position", "orientation"});
    Keyframe keyframe;
    keyframe.time = k.number("time", Interval::non_negative());
    if (!keyframes.empty() && !(keyframe.time > keyframes.back().time)) {
      k.fail("time", "expected a time after the previous keyframe's (" + std::to_string(keyframes.back().time) + " s)");
    }
    keyframe.pose.position = k.vec3("position");
    if (keyframe.pose.position.norm() > device.workspace_radius) {
      k.fail("position", "outside the device workspace: " + std::to_string(keyframe.pose.position.norm()) +
                             " m from the device origin, radius " + std::to_string(device.workspace_radius) + " m");
    }
    // An orientation left out keeps the previous keyframe's, so a purely translational script
    // names none.
    const Eigen::Quaterniond previous =
        keyframes.empty() ? Eigen::Quaterniond::Identity() : keyframes.back().pose.orientation;
    keyframe.pose.orientation = k.quaternion_or("orientation", previous);
    keyframes.push_back(keyframe);
  }
  if (keyframes.empty()) reader.fail_here("expected at least one keyframe");
  return keyframes;
}

TrajectoryConfig read_trajectory(const JsonReader& reader, const DeviceConfig& device) {
  reader.allow_only({"source", "keyframes", "hand", "file"});
  TrajectoryConfig trajectory;
  const std::string source = reader.choice_or("source", "free", {"free", "scripted", "recorded"});
  // Keys of another source are an error, not silently ignored.
  const auto only_for = [&](const char* key, const char* wanted) {
    if (reader.has(key) && source != wanted) {
      reader.fail(key,
                  std::string("applies to the \"") + wanted + "\" source only (this trajectory is \"" + source + "\")");
    }
  };
  only_for("keyframes", "scripted");
  only_for("hand", "scripted");
  only_for("file", "recorded");
  if (source == "scripted") {
    trajectory.source = TrajectorySource::scripted;
    trajectory.keyframes = read_keyframes(reader.child("keyframes"), device);
    trajectory.hand = read_gains_or(reader, "hand", trajectory.hand);
  } else if (source == "recorded") {
    trajectory.source = TrajectorySource::recorded;
    const std::filesystem::path file = reader.string("file");
    trajectory.file = (file.is_absolute() ? file : std::filesystem::path(reader.file()).parent_path() / file).string();
    trajectory.recording = read_device_recording(trajectory.file, RecordingLimits{device.workspace_radius});
  }
  return trajectory;
}

}  // namespace

const char* to_string(TrajectorySource source) {
  switch (source) {
    case TrajectorySource::free:
      return "free";
    case TrajectorySource::scripted:
      return "scripted";
    case TrajectorySource::recorded:
      return "recorded";
  }
  return "?";
}

HapticsConfig read_haptics_config(const JsonReader& proxy) {
  proxy.allow_only({"body", "haptic_rate_hz", "between_steps", "coupling", "device", "trajectory", "description"});
  proxy.string_or("description", "");  // documentation only, but a string like everywhere else
  HapticsConfig config;
  // A haptic device runs at about 1 kHz; 100 kHz leaves room for studies of the rate while
  // keeping one step's ticks (rate x dt) short enough that a signal is answered promptly.
  config.haptic_rate_hz = proxy.number_or("haptic_rate_hz", config.haptic_rate_hz, Interval{0.0, 1e5, true, false});
  config.between_steps = proxy.choice_or("between_steps", "hold", {"hold", "linearised"}) == "hold"
                             ? BetweenSteps::hold
                             : BetweenSteps::linearised;
  config.coupling = read_gains_or(proxy, "coupling", config.coupling);
  if (const auto device = proxy.optional_child("device")) config.device = read_device(*device);
  if (const auto trajectory = proxy.optional_child("trajectory")) {
    config.trajectory = read_trajectory(*trajectory, config.device);
  }
  return config;
}

}  // namespace mssph
