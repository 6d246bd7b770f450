// Resume: completed points are skipped, failed ones only rerun with --retry-failed, anything else
// runs again; shards together run every point once, and merge lists what is missing.
#include "io/run_log.hpp"
#include "sweep_cli_fixture.hpp"
#include "sweep_test_files.hpp"

#include <gmock/gmock.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

class SweepResume : public SweepCli {
 protected:
  ProcessResult sweep(std::vector<std::string> extra = {}, const std::string& file = tiny_product_sweep()) {
    std::vector<std::string> args{"sweep", file, "--out", out(), "--backend", "cpu"};
    args.insert(args.end(), extra.begin(), extra.end());
    return mssph(args);
  }
  std::vector<ino_t> inodes() const {
    std::vector<ino_t> out;
    for (std::size_t i = 0; i < 4; ++i) out.push_back(inode(log_of(i)));
    return out;
  }
  TempDir files_;
};

TEST_F(SweepResume, ASecondRunSkipsEveryCompletedPoint) {
  ASSERT_EQ(sweep().exit_code, 0);
  const std::vector<ino_t> before = inodes();
  const ProcessResult again = sweep();
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("4 completed before, 0 failed before, 0 to run"));
  EXPECT_EQ(inodes(), before) << "no log was rewritten";
}

TEST_F(SweepResume, LogsLeftRunningOrInterruptedRunAgain) {
  ASSERT_EQ(sweep().exit_code, 0);
  const std::vector<ino_t> before = inodes();
  // What runs of points 1 and 2 that did not finish leave: their log, with their scene, at
  // <log>.partial, "running" (killed mid-way) or "interrupted"; point 3's log is gone.
  const auto scene_of = [&](std::size_t i) {
    RunMetadata metadata;
    metadata.config_json = h5::read_string_attribute(open_read_only(log_of(i)).id(), "config");
    return metadata;
  };
  const RunMetadata scene_1 = scene_of(1), scene_2 = scene_of(2);
  for (std::size_t i : {1u, 2u, 3u}) std::filesystem::remove(log_of(i));
  { RunLog killed(log_of(1), scene_1); }
  RunLog(log_of(2), scene_2).finish_failed("interrupted by a signal at t = 0.05 s");
  ASSERT_EQ(status_of(log_on_disk(1)), "running");
  const ProcessResult again = sweep();
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("1 completed before, 0 failed before, 3 to run"));
  EXPECT_EQ(inode(log_of(0)), before[0]);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(status_of(log_of(i)), "completed") << i;
}

// A log under a point's name that another scene wrote (by hand, or another sweep's) was counted
// as the point completed, and merged as its results.
TEST_F(SweepResume, ALogOfAnotherSceneUnderAPointsNameRunsAgain) {
  ASSERT_EQ(sweep().exit_code, 0);
  const std::string intended = h5::read_string_attribute(open_read_only(log_of(0)).id(), "config");
  std::filesystem::copy_file(log_of(1), log_of(0), std::filesystem::copy_options::overwrite_existing);
  const ProcessResult again = sweep();
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("3 completed before, 0 failed before, 1 to run"));
  EXPECT_THAT(again.err, HasSubstr("run again, its log replaced: point 1/4"));
  EXPECT_THAT(again.err, HasSubstr("not this point's log"));
  EXPECT_EQ(h5::read_string_attribute(open_read_only(log_of(0)).id(), "config"), intended);
}

// A point whose log another run holds (another sweep on the same --out) is busy, not bad input:
// it is not started, the others run, and the sweep ends incomplete (exit 1) instead of stopping
// with exit 2 "mssph run rejected its input".
TEST_F(SweepResume, APointAnotherRunIsWritingIsNotStarted) {
  const ProcessResult listed = sweep({"--dry-run"});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  const std::size_t name = listed.out.find("point-");
  ASSERT_NE(name, std::string::npos) << listed.out;
  const std::string log = out() + "/points/" + listed.out.substr(name, listed.out.find(".h5", name) + 3 - name);
  std::filesystem::create_directories(out() + "/points");
  const std::string partial = log + ".partial";
  std::ofstream(partial) << "being written";
  const int holder = open(partial.c_str(), O_RDWR);
  ASSERT_GE(holder, 0);
  ASSERT_EQ(flock(holder, LOCK_EX | LOCK_NB), 0);
  const ProcessResult r = sweep();
  close(holder);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("not started, busy: point 1/4"));
  EXPECT_THAT(r.err, HasSubstr("another run is writing it"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("rejected its input")));
  EXPECT_EQ(read_file(partial), "being written") << "the other run's log is left alone";
  EXPECT_FALSE(std::filesystem::exists(log.substr(0, log.size() - 3) + ".out")) << "nor its console output";
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(status_of(log_of(i)), "completed") << i;
}

TEST_F(SweepResume, FailedPointsAreReportedAndRerunOnlyWhenAsked) {
  // The second point's speed bound is below what the falling ball reaches: a blow-up (exit 3).
  const std::string file = write_json(files_, "failing.json",
                                      tiny_sweep({{{"path", "simulation/max_speed"}, {"values", {20.0, 1e-4}}}},
                                                 {{"set", {{"simulation/duration", 0.02}}}}));
  const ProcessResult first = sweep({}, file);
  EXPECT_EQ(first.exit_code, 3) << first.err;
  EXPECT_THAT(first.err, HasSubstr("FAILED (failed: blow-up"));
  ASSERT_EQ(status_of(log_of(0)), "completed");
  // A rerun rewrites the partial file in place (same inode): its modification time tells.
  const auto failed = std::filesystem::last_write_time(log_on_disk(1));
  EXPECT_EQ(log_on_disk(1), log_of(1) + ".partial") << "a failed run's log keeps its partial name";

  const ProcessResult resumed = sweep({}, file);
  EXPECT_EQ(resumed.exit_code, 3) << "the sweep is still not complete";
  EXPECT_THAT(resumed.err, HasSubstr("1 completed before, 1 failed before, 0 to run"));
  EXPECT_THAT(resumed.err, HasSubstr("not rerun (--retry-failed reruns it): point 2/2 (max_speed=0.0001)"));
  EXPECT_EQ(std::filesystem::last_write_time(log_on_disk(1)), failed);
  EXPECT_EQ(csv_column("state"), (std::vector<std::string>{"completed", "failed"}));

  const ProcessResult retried = sweep({"--retry-failed"}, file);
  EXPECT_EQ(retried.exit_code, 3);
  EXPECT_THAT(retried.err, HasSubstr("1 completed before, 0 failed before, 1 to run"));
  EXPECT_NE(std::filesystem::last_write_time(log_on_disk(1)), failed) << "the failed point ran again";
}

TEST_F(SweepResume, ShardsTogetherRunEveryPointAndMergeListsTheMissing) {
  const ProcessResult first = sweep({"--shard", "0/2"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_THAT(first.err, HasSubstr("(shard 0/2: 2 of them)"));
  EXPECT_TRUE(log_exists(0) && log_exists(2));
  EXPECT_FALSE(log_exists(1) || log_exists(3));
  EXPECT_FALSE(std::filesystem::exists(out() + "/summary.csv")) << "a shard leaves the summary to the merge";

  const ProcessResult partial = mssph({"sweep", "merge", out()});
  ASSERT_EQ(partial.exit_code, 0) << partial.err;
  EXPECT_THAT(partial.out, HasSubstr("4 points, 2 completed, 0 failed, 0 interrupted, 0 incomplete, 2 missing"));
  EXPECT_THAT(partial.out, HasSubstr("missing: point 1 " + manifest()["points"][1]["log"].get<std::string>()));
  EXPECT_THAT(partial.out, HasSubstr("missing: point 3 "));
  EXPECT_EQ(csv_column("state"), (std::vector<std::string>{"completed", "missing", "completed", "missing"}));
  EXPECT_EQ(csv_column("peak_interaction_force")[1], "") << "a missing point has no metrics";

  // The second shard from a Slurm array task's environment.
  setenv("SLURM_ARRAY_TASK_ID", "1", 1);
  setenv("SLURM_ARRAY_TASK_COUNT", "2", 1);
  const ProcessResult second = sweep();
  unsetenv("SLURM_ARRAY_TASK_ID");
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_THAT(second.err, HasSubstr("(shard 1/2: 2 of them)"));
  const ProcessResult whole = mssph({"sweep", "merge", out()});
  EXPECT_THAT(whole.out, HasSubstr("4 points, 4 completed"));
  EXPECT_EQ(csv_column("state"), std::vector<std::string>(4, "completed"));
}

}  // namespace
}  // namespace mssph::test
