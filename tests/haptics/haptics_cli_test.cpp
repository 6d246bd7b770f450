// The haptics of `mssph run` end to end on a tiny scene (tests/haptics/data/poke.json): device
// recordings round-trip, bad recordings and requests stop the run before any output, gains
// beyond the stability bound are reported and show in the run.
#include "config/device_recording.hpp"
#include "haptics_cli_support.hpp"
#include "temp_dir.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace mssph::test {
namespace {

const std::string kPoke = MSSPH_SOURCE_DIR "/tests/haptics/data/poke.json";

std::string replaying(const std::string& file) {
  return "proxy/trajectory=" + nlohmann::json{{"source", "recorded"}, {"file", file}}.dump();
}

TEST(RecordedTrajectory, AScriptedRunReplaysWithTheSameDevicePosesInBothFormats) {
  TempDir dir;
  const auto at = [&](const char* name) { return (dir / name).string(); };
  // Scripted -> CSV; replaying the CSV -> HDF5; replaying the HDF5 -> CSV again.
  ProcessResult r =
      run_mssph({"run", kPoke, "--out", at("scripted.h5"), "--record-device", at("scripted.csv"), "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_mssph({"run", kPoke, "--out", at("replay.h5"), "--set", replaying(at("scripted.csv")), "--record-device",
                 at("replayed.h5"), "-q"},
                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_mssph({"run", kPoke, "--out", at("replay_again.h5"), "--set", replaying(at("replayed.h5")), "--record-device",
                 at("replayed_again.csv"), "-q"},
                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const RecordingLimits workspace{0.45};
  const DeviceRecording original = read_device_recording(at("scripted.csv"), workspace);
  ASSERT_EQ(original.time.size(), 401u);  // 0.4 s at 1 kHz, both ends
  double travel = 0.0;
  for (const Pose& p : original.pose) travel = std::max(travel, p.position.norm());
  EXPECT_GT(travel, 0.05) << "the hand moved the device";
  for (const char* replay : {"replayed.h5", "replayed_again.csv"}) {
    const DeviceRecording again = read_device_recording(at(replay), workspace);
    ASSERT_EQ(again.time, original.time) << replay;
    double worst = 0.0;
    for (std::size_t i = 0; i < again.pose.size(); ++i) {
      worst = std::max({worst, (again.pose[i].position - original.pose[i].position).norm(),
                        again.pose[i].orientation.angularDistance(original.pose[i].orientation)});
    }
    RecordProperty(std::string("largest_pose_difference_") + replay, std::to_string(worst));
    EXPECT_LE(worst, 1e-6) << replay;  // the requirement; the formats store every double exactly
  }
  // The replay's run log shows the same device poses as the original's.
  const auto logged = read_vec3(open_read_only(at("scripted.h5")).id(), "/haptics/device/position");
  const auto replayed = read_vec3(open_read_only(at("replay.h5")).id(), "/haptics/device/position");
  ASSERT_EQ(logged.size(), replayed.size());
  for (std::size_t i = 0; i < logged.size(); ++i) ASSERT_LE((logged[i] - replayed[i]).norm(), 1e-6) << "tick " << i;
}

TEST(RecordedTrajectory, ABadFileStopsTheRunWithExitCode2NamingFileAndRow) {
  TempDir dir;
  const std::string bad = (dir / "hand.csv").string();
  std::ofstream(bad) << "t,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n0.001,0,0,0,0,0,0,1\n0.001,0,0,0.01,0,0,0,1\n";
  const ProcessResult r =
      run_mssph({"run", kPoke, "--out", (dir / "run.h5").string(), "--set", replaying(bad)}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr(bad + ": line 4: t = 0.001 s is not after the previous sample's"));
  EXPECT_FALSE(std::filesystem::exists(dir / "run.h5")) << "rejected before any output";
}

TEST(RecordDevice, NeedsAProxyAndAKnownFormat) {
  TempDir dir;
  ProcessResult r =
      run_mssph({"run", kPoke, "--out", (dir / "run.h5").string(), "--record-device", "poses.txt"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("poses.txt: unknown device recording format \".txt\""));

  nlohmann::json scene = nlohmann::json::parse(std::ifstream(kPoke));
  scene.erase("proxy");
  const std::string no_proxy = (dir / "no_proxy.json").string();
  std::ofstream(no_proxy) << scene.dump();
  r = run_mssph({"run", no_proxy, "--out", (dir / "run.h5").string(), "--record-device", "poses.csv"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("has no \"proxy\""));
  EXPECT_FALSE(std::filesystem::exists(dir / "run.h5"));
}

TEST(CouplingGains, StableDefaultsRunPassivelyWithoutWarnings) {
  TempDir dir;
  const std::string out = (dir / "run.h5").string();
  const ProcessResult r = run_mssph({"run", kPoke, "--out", out, "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, ::testing::Not(::testing::HasSubstr("warning: proxy")));
  EXPECT_THAT(r.out, ::testing::HasSubstr(", peak rendered force "));
  const h5::Handle file = open_read_only(out);
  EXPECT_EQ(read_integer_attribute(open_object(file.id(), "/haptics").id(), "ticks"), 401);
  EXPECT_EQ(read_integer_attribute(open_object(file.id(), "/haptics").id(), "proxy_state_queries"), 401);
  // The coupling dissipates. Its passivity observer charges each tick's held wrench against that
  // tick's displacement: where the relative velocity reverses within a tick (here the hand jerks
  // the handle from rest at t = 0) the sampled damping term does a little positive work, an
  // error second order in the tick, far below what the run dissipates.
  const double balance = haptics_attribute(file.id(), "energy_balance_J");
  const double most = haptics_attribute(file.id(), "max_injected_energy_J");
  RecordProperty("energy_balance_J", std::to_string(balance));
  RecordProperty("max_injected_energy_J", std::to_string(most));
  EXPECT_LT(balance, 0.0);
  EXPECT_LE(most, 1e-3 * -balance);
  EXPECT_GT(haptics_attribute(file.id(), "peak_rendered_force_N"), 1.0);  // the poke was felt
  EXPECT_EQ(h5::read_string_attribute(open_object(file.id(), "/haptics/rendered/force").id(), "units"), "N");
  EXPECT_EQ(read_doubles(file.id(), "/haptics/time").size(), 401u);
}

TEST(CouplingGains, BeyondTheBoundTheRunWarnsAndShowsTheInstability) {
  TempDir dir;
  const std::string out = (dir / "run.h5").string();
  // Kt = 5e6 N/m on a 0.36 kg probe: Kt h^2 = 5 >= 4 m = 1.5 at h = 1 ms.
  const ProcessResult r =
      run_mssph({"run", kPoke, "--out", out, "--set", R"(proxy/coupling={"linear_stiffness": 5e6})", "-q"}, dir.path());
  EXPECT_THAT(r.err, ::testing::HasSubstr("warning: proxy \"probe\": translational coupling gains exceed the explicit "
                                          "stability bound K h^2 + 2 B h < 4 m"));
  // The coupling pumps energy in until the probe outruns simulation/max_speed: a blow-up.
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const h5::Handle file = open_read_only(out + ".partial");  // a failed run's log keeps its partial name
  EXPECT_GT(haptics_attribute(file.id(), "energy_balance_J"), 0.0);
}

}  // namespace
}  // namespace mssph::test
