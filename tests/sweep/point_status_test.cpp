// What resume makes of a point's log: only "completed" is done.
#include "sweep/point_status.hpp"
#include "io/run_log.hpp"
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
  EXPECT_EQ(sweep::read_point_status((dir / "absent.h5").string()).state, PointState::missing);
  const std::string garbage = (dir / "garbage.h5").string();
  std::ofstream(garbage) << "not HDF5";
  EXPECT_EQ(sweep::read_point_status(garbage).state, PointState::incomplete);

  const std::string running = (dir / "running.h5").string();
  { RunLog log(running, RunMetadata{}); }  // destroyed unfinished: what a killed run leaves
  EXPECT_EQ(sweep::read_point_status(running).state, PointState::incomplete);
  EXPECT_EQ(sweep::read_point_status(running).status, "running");

  const std::string done = (dir / "done.h5").string();
  RunLog(done, RunMetadata{}).finish_completed();
  EXPECT_EQ(sweep::read_point_status(done).state, PointState::completed);

  const std::string failed = (dir / "failed.h5").string();
  RunLog(failed, RunMetadata{}).finish_failed("blow-up at t = 1 s");
  EXPECT_EQ(sweep::read_point_status(failed).state, PointState::failed);
  EXPECT_EQ(sweep::read_point_status(failed).status, "failed: blow-up at t = 1 s");
}

}  // namespace
}  // namespace mssph::test
