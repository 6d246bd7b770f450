// Runs that do not complete: a blow-up (exit 3), SIGTERM (status "interrupted: SIGTERM ...",
// exit 143), and SIGKILL (a file h5py opens, status "running", the rows flushed so far). None of
// them leaves a file at --out: their logs keep the name <out>.partial.
#include "cli_fixture.hpp"
#include "python_tools.hpp"

#include <algorithm>
#include <csignal>
#include <functional>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

// Long enough that a run is still going when the test signals it; the scene's
// output/flush_interval of 0.1 s puts rows on disk many times a second meanwhile. At the tiny
// drop's own 5 cm spacing it steps so fast that its per-tick haptic rows and per-step timings make
// a log of a hundred megabytes in the seconds a test waits, which h5py then reads whole; at 2 cm
// (3,600 particles, stepped within their acoustic bound) the log stays a few megabytes.
const std::vector<std::string> kLongRun{
    "--set", "simulation/duration=1000", "--set", "simulation/particle_spacing=0.02", "--set", "simulation/dt=0.00025"};

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Every body series holds as many rows as /time (they are appended and flushed together), and
// the times increase.
void expect_consistent_series(const nlohmann::json& summary) {
  const nlohmann::json& time = summary["objects"]["/time"];
  const auto rows = time["shape"][0].get<std::size_t>();
  for (const auto& [path, object] : summary["objects"].items()) {
    if (path.rfind("/bodies/", 0) == 0 && object["kind"] == "dataset") {
      EXPECT_EQ(object["shape"][0].get<std::size_t>(), rows) << path;
    }
  }
  const std::vector<double> t = time["data"].get<std::vector<double>>();
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end(), std::less_equal<>())) << "times must increase";
}

using RunFailure = Cli;

TEST_F(RunFailure, SpeedBeyondMaxSpeedIsABlowUp) {
  const std::string out = work("blow_up.h5");
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", out, "--set", "simulation/max_speed=1e-4", "-q"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("blow-up"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(out + ".partial"), std::string::npos) << "the kept log is named:\n" << r.err;
  EXPECT_EQ(status_of(out + ".partial").rfind("failed: blow-up", 0), 0u) << status_of(out + ".partial");
  EXPECT_FALSE(std::filesystem::exists(out)) << "only a completed log takes the --out name";
}

TEST_F(RunFailure, AnAbsurdTimeStepIsABlowUp) {
  const std::string out = work("absurd_dt.h5");
  // A stiff contact (k = 1e5 m^2/s^2) stepped at over 100 times its acoustic bound
  // 0.25 h / sqrt(k) = 7.9e-5 s; the start-up warning says so.
  const ProcessResult r =
      mssph({"run", kTinyDrop, "--out", out, "--set", "materials/contact/pressure_stiffness=1e5", "--set",
             "simulation/dt=0.01", "--set", "simulation/duration=1", "--set", "output/log_interval=0", "-q"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_EQ(status_of(out + ".partial").rfind("failed: blow-up", 0), 0u) << status_of(out + ".partial");
  expect_consistent_series(h5py_summary(out + ".partial"));
}

TEST_F(RunFailure, SigtermMarksTheLogInterrupted) {
  const std::string out = work("terminated.h5");
  const auto run = start(concat({"run", kTinyDrop, "--out", out}, kLongRun));
  // The progress line (after a few seconds) shows the run is well under way.
  ASSERT_TRUE(wait_for([&] { return run->stderr_so_far().find("  step ") != std::string::npos; }, 60s))
      << "no progress line on stderr:\n"
      << run->stderr_so_far();
  run->send(SIGTERM);
  const ProcessResult r = run->wait();
  EXPECT_EQ(r.exit_code, 143) << r.err;  // 128 + SIGTERM, as a shell reports a terminated job
  const std::string kept = out + ".partial";
  EXPECT_NE(r.err.find(kept), std::string::npos) << "the kept log is named:\n" << r.err;
  EXPECT_EQ(status_of(kept).rfind("interrupted: SIGTERM after step ", 0), 0u) << status_of(kept);
  EXPECT_FALSE(std::filesystem::exists(out));
  const nlohmann::json summary = h5py_summary(kept);
  EXPECT_GT(summary["objects"]["/time"]["shape"][0].get<std::size_t>(), 0u);
  EXPECT_GT(summary["attributes"]["steps"].get<long long>(), 0);
  expect_consistent_series(summary);
}

TEST_F(RunFailure, SigkillLeavesARunningLogWithTheFlushedRows) {
  const std::string out = work("killed.h5");
  const auto run = start(concat({"run", kTinyDrop, "--out", out, "-q"}, kLongRun));
  // Past the first progress report (due after 3 s without -q), so the quiet check below means
  // something, and many flush intervals.
  std::this_thread::sleep_for(4s);
  ASSERT_TRUE(run->running()) << run->wait().err;
  run->send(SIGKILL);
  const ProcessResult r = run->wait();
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_EQ(r.err, "") << "-q prints no progress";
  EXPECT_FALSE(std::filesystem::exists(out));
  const nlohmann::json summary = h5py_summary(out + ".partial");
  EXPECT_EQ(summary["attributes"]["status"], "running");
  EXPECT_GT(summary["objects"]["/time"]["shape"][0].get<std::size_t>(), 0u) << "rows flushed before the kill";
  expect_consistent_series(summary);
}

// Killed the moment its partial file appears (before HDF5 has written anything to it, at
// times): nothing at --out; the next run refuses the leftover without --force and replaces it
// with it.
TEST_F(RunFailure, SigkillAsSoonAsThePartialFileAppearsLeavesNothingAtTheFinalPath) {
  const std::string out = work("killed_at_start.h5");
  const auto run = start(concat({"run", kTinyDrop, "--out", out, "-q"}, kLongRun));
  ASSERT_TRUE(wait_for([&] { return std::filesystem::exists(out + ".partial") || !run->running(); }, 60s));
  run->send(SIGKILL);
  EXPECT_EQ(run->wait().signal, SIGKILL);
  EXPECT_FALSE(std::filesystem::exists(out));
  const ProcessResult refused = mssph({"run", kTinyDrop, "--out", out, "-q"});
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("did not finish"), std::string::npos) << refused.err;
  const ProcessResult again = mssph({"run", kTinyDrop, "--out", out, "-q", "--force"});
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(status_of(out), "completed");
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

}  // namespace
}  // namespace mssph::test
