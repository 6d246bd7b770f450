#pragma once
// The haptic device of a scene (paper section 4.1, docs/model.md): every key of the scene's
// "proxy" section besides "body", typed and validated, SI units. Keys, units and defaults are
// documented in configs/README.md ("Proxy and haptic device").
#include "config/device_recording.hpp"

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace mssph {

class JsonReader;

// A 6DoF spring-damper: the virtual coupling (Colgate, Stanley and Brown 1995) between the
// handle and the proxy, and the simulated hand holding the handle.
struct SpringDamperGains {
  double linear_stiffness = 0.0;   // Kt [N/m]
  double linear_damping = 0.0;     // Bt [N s/m]
  double angular_stiffness = 0.0;  // Kr [N m/rad]
  double angular_damping = 0.0;    // Br [N m s/rad]
};

// Device frame -> scene frame: p_scene = offset + scale R p_device, q_scene = R q_device.
struct WorkspaceConfig {
  double scale = 1.0;  // scene metres per device metre [-]
  // Scene position of the device origin [m]; unset: the proxy's initial centre of mass.
  std::optional<Eigen::Vector3d> offset;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

// A Virtuose 6D35-45 (Haption): force, torque and workspace limits from its public data. The
// handle's apparent mass, inertia and damping are not published; the defaults are plausible
// values for an arm of this size, to be set from a measurement.
struct DeviceConfig {
  double mass = 0.4;               // apparent mass of the handle [kg]
  double inertia = 1e-3;           // apparent rotational inertia of the handle, isotropic [kg m^2]
  double linear_damping = 2.0;     // [N s/m]
  double angular_damping = 0.02;   // [N m s/rad]
  double max_force = 30.0;         // [N]
  double max_torque = 3.0;         // [N m]
  double workspace_radius = 0.45;  // handle positions within this distance of the device origin [m]
  double force_scale = 1.0;        // rendered force per coupling force [-]
  double torque_scale = 1.0;       // rendered torque per coupling torque [-]
  WorkspaceConfig workspace;
};

enum class TrajectorySource {
  free,      // no hand: the handle follows the proxy (e.g. the Figure 3 drop)
  scripted,  // a simulated hand leads the handle through keyframes
  recorded,  // the handle replays a recorded trajectory
};

// How the coupling sees the proxy at haptic ticks between two simulation states.
enum class BetweenSteps {
  hold,        // the latest simulated state
  linearised,  // a local rigid-body model about the latest state (see proxy_predictor.hpp)
};

struct Keyframe {
  double time = 0.0;  // [s]
  Pose pose;          // handle target, device frame
};

struct TrajectoryConfig {
  TrajectorySource source = TrajectorySource::free;
  std::vector<Keyframe> keyframes;                // scripted
  SpringDamperGains hand{400.0, 20.0, 5.0, 0.1};  // scripted: the hand holding the handle
  std::string file;                               // recorded: the file, resolved against the scene's folder
  DeviceRecording recording;                      // recorded: its validated samples
};

struct HapticsConfig {
  double haptic_rate_hz = 1000.0;  // [Hz]
  BetweenSteps between_steps = BetweenSteps::hold;
  SpringDamperGains coupling{1000.0, 10.0, 10.0, 0.1};
  DeviceConfig device;
  TrajectoryConfig trajectory;
};

// Reads the haptics keys of the scene's "proxy" section (whose "body" the scene loader reads);
// a recorded trajectory's file is read and validated here, before any output exists.
HapticsConfig read_haptics_config(const JsonReader& proxy);

const char* to_string(TrajectorySource source);

}  // namespace mssph
