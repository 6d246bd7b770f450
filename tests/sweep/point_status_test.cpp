// What resume makes of a point's log: only "completed" is done.
#include "sweep/point_status.hpp"
#include "io/run_log.hpp"
#include "sweep/sweep_points.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace mssph::test {
namespace {

using sweep::PointState;

TEST(PointStatus, OnlyCompletedIsDone) {
  EXPECT_EQ(sweep::classify_status("completed"), PointState::completed);
  EXPECT_EQ(sweep::classify_status("failed: blow-up at t = 0.1 s"), PointState::failed);
  EXPECT_EQ(sweep::classify_status("failed: interrupted by a signal at t = 0.2 s"), PointState::interrupted);
  EXPECT_EQ(sweep::classify_status("interrupted by a signal at t = 0.2 s"), PointState::interrupted);
  EXPECT_EQ(sweep::classify_status("running"), PointState::incomplete);
  EXPECT_EQ(sweep::classify_status(""), PointState::incomplete);
  EXPECT_EQ(sweep::classify_status("completed, more or less"), PointState::incomplete);
}

TEST(PointStatus, ReadFromTheLogFile) {
  TempDir dir;
  // The point's scene, as `mssph run` records it in the log's `config` attribute.
  RunMetadata point;
  point.config_json = R"({"name": "p", "simulation": {"dt": 0.001}})";
  const std::string hash = sweep::point_hash(nlohmann::json::parse(point.config_json));
  EXPECT_EQ(sweep::read_point_status((dir / "absent.h5").string(), hash).state, PointState::missing);
  const std::string garbage = (dir / "garbage.h5").string();
  std::ofstream(garbage) << "not HDF5";
  EXPECT_EQ(sweep::read_point_status(garbage, hash).state, PointState::incomplete);

  const std::string running = (dir / "running.h5").string();
  { RunLog log(running, point); }  // destroyed unfinished: what a killed run leaves
  EXPECT_EQ(sweep::read_point_status(running, hash).state, PointState::incomplete);
  EXPECT_EQ(sweep::read_point_status(running, hash).status, "running");

  const std::string done = (dir / "done.h5").string();
  RunLog(done, point).finish_completed();
  EXPECT_EQ(sweep::read_point_status(done, hash).state, PointState::completed);

  const std::string failed = (dir / "failed.h5").string();
  RunLog(failed, point).finish_failed("blow-up at t = 1 s");
  EXPECT_EQ(sweep::read_point_status(failed, hash).state, PointState::failed);
  EXPECT_EQ(sweep::read_point_status(failed, hash).status, "failed: blow-up at t = 1 s");
}

// A completed log of another scene under the point's name is not the point's: it runs again.
TEST(PointStatus, ALogOfAnotherSceneIsForeign) {
  TempDir dir;
  RunMetadata other;
  other.config_json = R"({"name": "p", "simulation": {"dt": 0.002}})";
  const std::string done = (dir / "done.h5").string();
  RunLog(done, other).finish_completed();
  const std::string hash = sweep::point_hash(nlohmann::json::parse(R"({"name": "p", "simulation": {"dt": 0.001}})"));
  const sweep::PointStatus status = sweep::read_point_status(done, hash);
  EXPECT_EQ(status.state, PointState::foreign);
  EXPECT_NE(status.status.find("hashes to " + sweep::point_hash(nlohmann::json::parse(other.config_json))),
            std::string::npos)
      << status.status;
  const std::string unnamed = (dir / "unnamed.h5").string();
  RunLog(unnamed, RunMetadata{}).finish_completed();  // no scene recorded at all
  EXPECT_EQ(sweep::read_point_status(unnamed, hash).state, PointState::foreign);
}

// A log another run holds (its lock on <log>.partial) is busy, whatever the file holds.
TEST(PointStatus, ALogAnotherRunHoldsIsBusy) {
  TempDir dir;
  RunMetadata point;
  point.config_json = R"({"name": "p"})";
  const std::string path = (dir / "live.h5").string();
  RunLog live(path, point);
  const sweep::PointStatus status = sweep::read_point_status(path, sweep::point_hash(nlohmann::json::parse("{}")));
  EXPECT_EQ(status.state, PointState::busy);
  EXPECT_NE(status.status.find("another run is writing it"), std::string::npos) << status.status;
}

}  // namespace
}  // namespace mssph::test
