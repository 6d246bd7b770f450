// The haptics keys of a scene's "proxy" section: defaults, values, and errors that name the file,
// the JSON path and what was expected.
#include "config/device_recording.hpp"
#include "config/scene_loader.hpp"
#include "temp_dir.hpp"
#include "util/errors.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace mssph::test {
namespace {

nlohmann::json scene_with_proxy(const nlohmann::json& proxy) {
  nlohmann::json scene = nlohmann::json::parse(R"({
    "name": "probe_only",
    "simulation": {"dt": 0.00025, "duration": 0.1, "particle_spacing": 0.02},
    "bodies": {"probe": {"kind": "rigid", "shape": {"type": "sphere", "radius": 0.05}, "density": 100.0,
                         "rest_density": 1000.0, "pressure_stiffness": 100.0}}
  })");
  scene["proxy"] = proxy;
  return scene;
}

HapticsConfig parse(const nlohmann::json& proxy, const std::string& file = "scene.json") {
  return parse_scene(scene_with_proxy(proxy), file).proxy->haptics;
}

void expect_error(const nlohmann::json& proxy, const std::string& where, const std::string& what) {
  try {
    parse(proxy);
    ADD_FAILURE() << "accepted " << proxy.dump();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("scene.json: " + where + ": ")) << proxy.dump();
    EXPECT_THAT(e.what(), ::testing::HasSubstr(what)) << proxy.dump();
  }
}

TEST(HapticsConfig, ABodyAloneGetsAFreeVirtuoseWithDefaultGains) {
  const HapticsConfig c = parse({{"body", "probe"}});
  EXPECT_EQ(c.haptic_rate_hz, 1000.0);
  EXPECT_EQ(c.between_steps, BetweenSteps::hold);
  EXPECT_EQ(c.trajectory.source, TrajectorySource::free);
  EXPECT_EQ(c.device.max_force, 30.0);
  EXPECT_EQ(c.device.max_torque, 3.0);
  EXPECT_EQ(c.device.workspace_radius, 0.45);
  EXPECT_FALSE(c.device.workspace.offset.has_value());  // the proxy's start, known at run time
  EXPECT_GT(c.coupling.linear_stiffness, 0.0);
}

TEST(HapticsConfig, ReadsEveryKey) {
  const HapticsConfig c = parse(nlohmann::json::parse(R"({
    "body": "probe", "haptic_rate_hz": 500, "between_steps": "linearised",
    "coupling": {"linear_stiffness": 800, "linear_damping": 5, "angular_stiffness": 2, "angular_damping": 0.05},
    "device": {"mass": 0.3, "inertia": 0.002, "linear_damping": 1, "angular_damping": 0.01, "max_force": 20,
               "max_torque": 2, "workspace_radius": 0.3, "force_scale": 0.5, "torque_scale": 0.25,
               "workspace": {"scale": 2, "offset": [0, 0, 0.4],
                             "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476]}},
    "trajectory": {"source": "scripted", "hand": {"linear_stiffness": 300},
                   "keyframes": [{"time": 0, "position": [0, 0, 0]},
                                 {"time": 0.5, "position": [0.1, 0, 0], "orientation": [0, 0, 1, 0]},
                                 {"time": 1.0, "position": [0, 0, 0]}]}
  })"));
  EXPECT_EQ(c.haptic_rate_hz, 500.0);
  EXPECT_EQ(c.between_steps, BetweenSteps::linearised);
  EXPECT_EQ(c.coupling.angular_damping, 0.05);
  EXPECT_EQ(c.device.force_scale, 0.5);
  EXPECT_EQ(c.device.workspace.scale, 2.0);
  EXPECT_EQ(*c.device.workspace.offset, Eigen::Vector3d(0, 0, 0.4));
  ASSERT_EQ(c.trajectory.keyframes.size(), 3u);
  EXPECT_EQ(c.trajectory.hand.linear_stiffness, 300.0);
  EXPECT_EQ(c.trajectory.hand.linear_damping, HapticsConfig{}.trajectory.hand.linear_damping);  // default kept
  // A keyframe without an orientation keeps the previous one's.
  EXPECT_NEAR(c.trajectory.keyframes[2].pose.orientation.angularDistance(c.trajectory.keyframes[1].pose.orientation),
              0.0, 1e-15);
}

TEST(HapticsConfig, ErrorsNameThePathAndWhatWasExpected) {
  const auto with = [](const char* text) { return nlohmann::json::parse(text); };
  expect_error(with(R"({"body": "probe", "coupling": {"linear_stiffness": -1}})"), "/proxy/coupling/linear_stiffness",
               "expected a number >= 0");
  expect_error(with(R"({"body": "probe", "haptic_rate_hz": 0})"), "/proxy/haptic_rate_hz",
               "expected a number in (0, 100000]");
  expect_error(with(R"({"body": "probe", "between_steps": "interpolate"})"), "/proxy/between_steps",
               "expected one of \"hold\", \"linearised\"");
  expect_error(with(R"({"body": "probe", "devise": {}})"), "/proxy/devise", "did you mean 'device'");
  expect_error(with(R"({"body": "probe", "device": {"max_force": 0}})"), "/proxy/device/max_force", "> 0");
  expect_error(with(R"({"body": "probe", "device": {"workspace": {"rotation": [0, 0, 0, 2]}}})"),
               "/proxy/device/workspace/rotation", "unit quaternion");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "scripted"}})"), "/proxy/trajectory/keyframes",
               "missing required key");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "scripted", "keyframes": []}})"),
               "/proxy/trajectory/keyframes", "at least one keyframe");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "scripted", "keyframes":
                         [{"time": 0.5, "position": [0, 0, 0]}, {"time": 0.5, "position": [0, 0, 0.1]}]}})"),
               "/proxy/trajectory/keyframes/1/time", "after the previous keyframe's");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "scripted", "keyframes":
                         [{"time": 0, "position": [0.5, 0, 0]}]}})"),
               "/proxy/trajectory/keyframes/0/position", "outside the device workspace");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "free", "keyframes": []}})"),
               "/proxy/trajectory/keyframes", "applies to the \"scripted\" source only");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "scripted", "file": "a.csv",
                         "keyframes": [{"time": 0, "position": [0, 0, 0]}]}})"),
               "/proxy/trajectory/file", "applies to the \"recorded\" source only");
  expect_error(with(R"({"body": "probe", "trajectory": {"source": "recorded"}})"), "/proxy/trajectory/file",
               "missing required key");
}

TEST(HapticsConfig, RecordedFilesResolveAgainstTheSceneFolderAndAreValidatedAtLoad) {
  TempDir dir;
  DeviceRecording recording{{0.0, 0.001},
                            {Pose{}, Pose{Eigen::Vector3d(0.01, 0.0, 0.0), Eigen::Quaterniond::Identity()}}};
  const std::string hand = (dir / "hand.csv").string();
  std::ofstream(hand, std::ios::binary) << device_recording_bytes(hand, recording);
  const nlohmann::json proxy = {{"body", "probe"}, {"trajectory", {{"source", "recorded"}, {"file", "hand.csv"}}}};
  const HapticsConfig c = parse(proxy, (dir / "scene.json").string());
  EXPECT_EQ(c.trajectory.file, (dir / "hand.csv").string());
  EXPECT_EQ(c.trajectory.recording.time, recording.time);

  // The workspace radius of the scene's device applies: 1 cm is outside a 5 mm workspace.
  nlohmann::json small = proxy;
  small["device"] = {{"workspace_radius", 0.005}};
  EXPECT_THROW(parse(small, (dir / "scene.json").string()), InputError);
  nlohmann::json absent = proxy;
  absent["trajectory"]["file"] = "absent.csv";
  EXPECT_THAT([&] { parse(absent, (dir / "scene.json").string()); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr((dir / "absent.csv").string())));
}

}  // namespace
}  // namespace mssph::test
