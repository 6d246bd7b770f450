// An interrupted sweep (SIGTERM to it, or SIGKILL: a node lost) loses at most its point in flight,
// whose partial log is never taken as done, and the same command finishes the rest.
#include "sweep_cli_fixture.hpp"

#include <gmock/gmock.h>

#include <csignal>
#include <cstdlib>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

class SweepInterrupt : public SweepCli {
 protected:
  // The test reads the logs of points while they run (and lock their files).
  SweepInterrupt() { setenv("HDF5_USE_FILE_LOCKING", "FALSE", 1); }
  ~SweepInterrupt() override { unsetenv("HDF5_USE_FILE_LOCKING"); }

  // Points of 8,000 steps (about a second each on a quiet 2-core machine) for the signal to find
  // one running: 800 steps finished before the signal reached them.
  std::vector<std::string> args() const {
    return {"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cpu", "--set", "simulation/duration=4"};
  }
  // A log's status; "unreadable" while its run is rewriting the file's metadata (a reader
  // without SWMR can catch the file between two consistent states).
  std::string status_now(std::size_t i) const {
    try {
      return status_of(log_on_disk(i));
    } catch (const h5::Error&) {
      return "unreadable";
    }
  }
  std::size_t completed_logs() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < 4; ++i) n += log_exists(i) && status_now(i) == "completed" ? 1 : 0;
    return n;
  }
  // Waits until one point has completed and the next one's log exists: the sweep is mid-point.
  bool wait_for_a_point_in_flight(ChildProcess& sweep) {
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    while (std::chrono::steady_clock::now() < deadline && sweep.running()) {
      if (std::filesystem::exists(out() + "/sweep.json") && completed_logs() >= 1 && log_exists(1)) return true;
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }
  // After the signal: every log that is not completed; at most the one in flight may exist.
  std::vector<std::size_t> unfinished_logs() const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < 4; ++i) {
      if (log_exists(i) && status_now(i) != "completed") out.push_back(i);
    }
    return out;
  }
  void expect_resume_finishes(std::size_t completed_before) {
    std::vector<ino_t> kept;
    for (std::size_t i = 0; i < 4; ++i)
      kept.push_back(log_exists(i) && status_now(i) == "completed" ? inode(log_of(i)) : 0);
    const ProcessResult resumed = mssph(args());
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_THAT(resumed.err, HasSubstr(std::to_string(completed_before) + " completed before"));
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(status_of(log_of(i)), "completed") << i;
      if (kept[i]) {
        EXPECT_EQ(inode(log_of(i)), kept[i]) << "point " << i << " had completed and must not rerun";
      }
    }
  }
};

TEST_F(SweepInterrupt, SigtermStopsTheSweepAndItsRunningPoint) {
  auto sweep = start(args());
  ASSERT_TRUE(wait_for_a_point_in_flight(*sweep)) << sweep->stderr_so_far();
  sweep->send(SIGTERM);
  const ProcessResult r = sweep->wait(60s);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("interrupted: passing the signal on to 1 running point(s)"));
  EXPECT_THAT(r.err, HasSubstr("continue from it when the same command is repeated"));
  const std::vector<std::size_t> unfinished = unfinished_logs();
  ASSERT_EQ(unfinished.size(), 1u) << "only the point in flight is lost\n" << r.err;
  EXPECT_THAT(status_of(log_on_disk(unfinished[0])), HasSubstr("interrupted"));
  EXPECT_FALSE(std::filesystem::exists(out() + "/summary.h5")) << "an interrupted sweep writes no summary";
  expect_resume_finishes(completed_logs());
  // The stopped point wrote a checkpoint and continued from it rather than starting over.
  const h5::Handle log = open_read_only(log_of(unfinished[0]));
  EXPECT_THAT(h5::read_string_attribute(log.id(), "restarts"), HasSubstr("mssph run --restart"));
}

TEST_F(SweepInterrupt, SigkillLosesOnlyThePointInFlight) {
  auto sweep = start(args());
  ASSERT_TRUE(wait_for_a_point_in_flight(*sweep)) << sweep->stderr_so_far();
  sweep->send(SIGKILL);
  const ProcessResult r = sweep->wait(60s);
  EXPECT_EQ(r.signal, SIGKILL);
  // The orphaned point gets SIGTERM (its parent-death signal) and ends its log within a step.
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto unfinished = unfinished_logs();
    if (unfinished.empty() || (status_now(unfinished[0]) != "running" && status_now(unfinished[0]) != "unreadable"))
      break;
    std::this_thread::sleep_for(20ms);
  }
  const std::vector<std::size_t> unfinished = unfinished_logs();
  ASSERT_LE(unfinished.size(), 1u) << "only the point in flight may be unfinished";
  const std::size_t completed = completed_logs();
  EXPECT_GE(completed, 1u);
  expect_resume_finishes(completed);
}

}  // namespace
}  // namespace mssph::test
