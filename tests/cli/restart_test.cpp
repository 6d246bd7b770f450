// Checkpoints and `mssph run --restart`, through the real command line: a run stopped by SIGTERM
// (which writes a checkpoint) or killed by SIGKILL after a periodic checkpoint, then continued
// with --restart, ends with a log whose every dataset outside /timing (wall-clock times) and
// /checkpoint is bit-identical to the same run left alone; and a log that cannot be continued is
// refused with exit 2 and left as it was.
#include "backend_on_this_machine.hpp"
#include "cli_fixture.hpp"

#include <csignal>
#include <cstring>
#include <fstream>
#include <map>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

// Every dataset of a log but those under /timing and /checkpoint, as doubles (exact for the
// float32, float64 and integer datasets a log holds), by path.
std::map<std::string, std::vector<double>> logged_data(const std::string& path) {
  const h5::Handle file = open_read_only(path);
  std::vector<std::string> names;
  const auto collect = [](hid_t group, const char* name, const H5L_info_t*, void* data) -> herr_t {
    const h5::Handle object(H5Oopen(group, name, H5P_DEFAULT), H5Oclose, name);
    if (H5Iget_type(object.id()) == H5I_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  h5::check(H5Lvisit(file.id(), H5_INDEX_NAME, H5_ITER_INC, collect, &names), "list " + path);
  std::map<std::string, std::vector<double>> out;
  for (const std::string& name : names) {
    if (name.rfind("timing/", 0) == 0 || name.rfind("checkpoint/", 0) == 0) continue;
    out["/" + name] = read_doubles(file.id(), "/" + name);
  }
  return out;
}

// The same datasets, the same shapes, the same bits (NaN included).
void expect_bit_identical(const std::string& expected_log, const std::string& actual_log) {
  const auto expected = logged_data(expected_log);
  const auto actual = logged_data(actual_log);
  ASSERT_GT(expected.size(), 20u) << "the comparison covers the body, haptic and snapshot datasets";
  ASSERT_EQ(actual.size(), expected.size());
  for (const auto& [name, values] : expected) {
    const auto it = actual.find(name);
    ASSERT_NE(it, actual.end()) << name << " missing after the restart";
    ASSERT_EQ(it->second.size(), values.size()) << name;
    if (values.empty()) continue;  // memcmp of a possibly null data() is undefined even for zero bytes
    EXPECT_EQ(std::memcmp(it->second.data(), values.data(), values.size() * sizeof(double)), 0) << name << " differs";
  }
}

// Every kind of state a checkpoint carries: fluid, a deformable body (whose rotations seed the
// next step's), a fixed and a driven rigid body, the scripted haptic loop touching them all. At
// 5 cm spacing (426 particles) its 4.8 s take one to three seconds on each backend, so a signal
// sent a moment after the start lands mid-run.
const std::string kMixedScene = MSSPH_SOURCE_DIR "/configs/tap_squeeze_stir.json";

class Restart : public Cli, public ::testing::WithParamInterface<std::string> {
 protected:
  void SetUp() override {
    if (!backend_runs_here(GetParam())) GTEST_SKIP() << "no " << GetParam() << " backend here";
  }

  // With snapshots (so that those after the checkpoint must go) and a recording of the device
  // (whose earlier ticks live only in the checkpoint).
  std::vector<std::string> run_args(const std::string& out, const std::string& recording) const {
    return {"run",
            kMixedScene,
            "--backend",
            GetParam(),
            "--out",
            out,
            "--threads",
            "1",
            "--set",
            "simulation/particle_spacing=0.05",
            "--set",
            "output/snapshot_interval=0.5",
            "--record-device",
            recording};
  }

  void run_uninterrupted() {
    const ProcessResult whole = mssph(run_args(work("whole.h5"), work("whole.csv")));
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
  }

  // Starts the run to be stopped and waits until it is stepping.
  std::unique_ptr<ChildProcess> start_stopped_run(const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = run_args(work("stopped.h5"), work("stopped.csv"));
    args.insert(args.end(), extra.begin(), extra.end());
    auto run = start(args);
    // The start-up line comes before the backend is built; a few tenths of a second later the run
    // is logging (output/flush_interval 0.1 s) and far from its end.
    EXPECT_TRUE(wait_for([&] { return run->stderr_so_far().find(" particles (") != std::string::npos; }, 60s))
        << run->stderr_so_far();
    std::this_thread::sleep_for(300ms);
    return run;
  }

  void restart_and_compare() {
    const ProcessResult continued = mssph({"run", "--restart", work("stopped.h5.partial"), "-q"});
    ASSERT_EQ(continued.exit_code, 0) << continued.err;
    EXPECT_EQ(status_of(work("stopped.h5")), "completed");
    EXPECT_FALSE(std::filesystem::exists(work("stopped.h5.partial")));
    const h5::Handle log = open_read_only(work("stopped.h5"));
    EXPECT_NE(h5::read_string_attribute(log.id(), "restarts").find("mssph run --restart"), std::string::npos);
    expect_bit_identical(work("whole.h5"), work("stopped.h5"));
    EXPECT_EQ(read_file(work("stopped.csv")), read_file(work("whole.csv"))) << "the device recording";
  }
};

TEST_P(Restart, AfterSigtermEndsBitIdenticalToTheUninterruptedRun) {
  run_uninterrupted();
  auto run = start_stopped_run();
  run->send(SIGTERM);
  const ProcessResult stopped = run->wait();
  ASSERT_EQ(stopped.exit_code, 143) << "the run ended before the signal?\n" << stopped.err;
  const std::string status = status_of(work("stopped.h5.partial"));
  EXPECT_NE(status.find("checkpoint written"), std::string::npos) << status;
  restart_and_compare();
}

TEST_P(Restart, AfterSigkillContinuesFromTheLastPeriodicCheckpoint) {
  run_uninterrupted();
  auto run = start_stopped_run({"--checkpoint-interval", "0.05"});
  run->send(SIGKILL);
  ASSERT_EQ(run->wait().signal, SIGKILL);
  EXPECT_EQ(status_of(work("stopped.h5.partial")), "running");
  restart_and_compare();
}

INSTANTIATE_TEST_SUITE_P(Backends, Restart, ::testing::Values("cpu", "reference", "cuda"),
                         [](const auto& test) { return test.param; });

// Logs that cannot be continued: refused with exit 2, the file left as it was.
class RestartRefusal : public Cli {};

TEST_F(RestartRefusal, ACompletedRun) {
  ASSERT_EQ(mssph({"run", kTinyDrop, "--backend", "cpu", "--out", work("done.h5"), "-q"}).exit_code, 0);
  const ProcessResult r = mssph({"run", "--restart", work("done.h5")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("completed"), std::string::npos) << r.err;
}

TEST_F(RestartRefusal, ALogWithoutACheckpoint) {
  // A run killed before any checkpoint: no --checkpoint-interval, and SIGKILL writes none.
  auto run =
      start({"run", kTinyDrop, "--backend", "cpu", "--out", work("killed.h5"), "--set", "simulation/duration=1000"});
  ASSERT_TRUE(wait_for([&] { return run->stderr_so_far().find(" particles (") != std::string::npos; }, 60s));
  std::this_thread::sleep_for(300ms);
  run->send(SIGKILL);
  run->wait();
  const ProcessResult r = mssph({"run", "--restart", work("killed.h5.partial")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds no checkpoint"), std::string::npos) << r.err;
  EXPECT_EQ(status_of(work("killed.h5.partial")), "running");
}

// A checkpoint whose step lies past the run's end: the run stepped on for ever, ignoring SIGTERM.
TEST_F(RestartRefusal, ACheckpointStepPastTheRunsEnd) {
  auto run = start({"run", kTinyDrop, "--backend", "cpu", "--threads", "1", "--out", work("damaged.h5"), "--set",
                    "simulation/duration=1000"});
  ASSERT_TRUE(wait_for([&] { return run->stderr_so_far().find(" particles (") != std::string::npos; }, 60s));
  std::this_thread::sleep_for(300ms);
  run->send(SIGTERM);
  ASSERT_EQ(run->wait().exit_code, 143);
  {
    const h5::Handle log = h5::file(H5Fopen(work("damaged.h5.partial").c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "open");
    for (const char* slot : {"/checkpoint/a", "/checkpoint/b"}) {
      if (!h5::object_exists(log.id(), slot)) continue;
      const h5::Handle group = h5::group(H5Gopen2(log.id(), slot, H5P_DEFAULT), slot);
      h5::write_attribute(group.id(), "step", 1000000000000LL);
    }
  }
  const ProcessResult r = start({"run", "--restart", work("damaged.h5.partial"), "-q"})->wait(30s);
  ASSERT_FALSE(r.timed_out) << "still running 30 s later";
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("damaged.h5.partial: its latest checkpoint says step 1000000000000, outside the run's 0 to "
                       "2000000 steps"),
            std::string::npos)
      << r.err;
}

TEST_F(RestartRefusal, OptionsThatWouldChangeTheRun) {
  for (const std::vector<std::string>& extra : {std::vector<std::string>{"--set", "simulation/dt=1e-4"},
                                                {"--backend", "reference"},
                                                {"--out", "x.h5"},
                                                {kTinyDrop}}) {
    std::vector<std::string> args{"run", "--restart", work("any.h5.partial")};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << extra.front();
    EXPECT_NE(r.err.find("cannot be given with --restart"), std::string::npos) << r.err;
  }
}

TEST_F(RestartRefusal, AFileThatIsNoRunLog) {
  std::filesystem::copy_file(kTinyDrop, work("scene.h5.partial"));
  const ProcessResult r = mssph({"run", "--restart", work("scene.h5.partial")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not an HDF5 file"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(work("scene.h5.partial")), read_file(kTinyDrop)) << "left as it was";
}

TEST_F(RestartRefusal, ARunStillWritingItsLog) {
  auto run = start({"run", kTinyDrop, "--backend", "cpu", "--out", work("live.h5"), "--set", "simulation/duration=1000",
                    "--checkpoint-interval", "0.05"});
  ASSERT_TRUE(wait_for([&] { return run->stderr_so_far().find(" particles (") != std::string::npos; }, 60s));
  std::this_thread::sleep_for(300ms);
  const ProcessResult r = mssph({"run", "--restart", work("live.h5.partial")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("another run is writing it"), std::string::npos) << r.err;
  run->send(SIGKILL);
  run->wait();
}

// A refused or failed restart leaves the log as it was, byte for byte: each case below is a log
// stopped by SIGTERM (so it holds a checkpoint), then altered, then given to --restart.
class RestartLeavesTheLogAsItWas : public Cli {
 protected:
  const std::string log = work("stopped.h5");
  const std::string partial = log + ".partial";

  // tiny_drop with snapshots and a recording of its (free) device, stopped by SIGTERM.
  void stop_a_run() {
    auto run = start({"run", kTinyDrop, "--backend", "cpu", "--threads", "1", "--out", log, "--record-device",
                      work("hand.csv"), "--set", "output/snapshot_interval=0.005", "--set", "simulation/duration=20"});
    ASSERT_TRUE(wait_for([&] { return non_empty_file(partial); }, 60s)) << run->stderr_so_far();
    std::this_thread::sleep_for(200ms);
    run->send(SIGTERM);
    const ProcessResult stopped = run->wait();
    ASSERT_EQ(stopped.exit_code, 143) << stopped.err;
    EXPECT_FALSE(std::filesystem::exists(work("hand.csv"))) << "a recording is written only by a completed run";
  }

  // Removes the dataset or group at each path that exists (HDF5 C API, read-write).
  void remove_objects(const std::vector<std::string>& paths) const {
    const h5::Handle file = h5::file(H5Fopen(partial.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "open " + partial);
    for (const std::string& path : paths) {
      if (h5::object_exists(file.id(), path)) h5::check(H5Ldelete(file.id(), path.c_str(), H5P_DEFAULT), path);
    }
  }

  // --restart exits 2 naming the log and `fragment`, and the log's bytes are what they were.
  void expect_refused(const std::string& fragment) const {
    const std::string before = read_file(partial);
    const ProcessResult r = mssph({"run", "--restart", partial, "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(partial), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << "\"" << fragment << "\" in\n" << r.err;
    EXPECT_TRUE(read_file(partial) == before) << "the log was changed";
    EXPECT_FALSE(std::filesystem::exists(log));
  }
};

// K22: the checkpoint lacks an array the backend needs.
TEST_F(RestartLeavesTheLogAsItWas, ACheckpointThatCannotBeRestored) {
  ASSERT_NO_FATAL_FAILURE(stop_a_run());
  remove_objects({"/checkpoint/a/state/backend/position", "/checkpoint/b/state/backend/position"});
  expect_refused("no array \"position\"");
}

// K05: a snapshot the restart keeps is damaged.
TEST_F(RestartLeavesTheLogAsItWas, ADamagedSnapshot) {
  ASSERT_NO_FATAL_FAILURE(stop_a_run());
  remove_objects({"/snapshots/00000000/density"});
  expect_refused("damaged");
}

// K29: a file appeared at the recording's name since the run stopped.
TEST_F(RestartLeavesTheLogAsItWas, AFileAtTheRecordingsName) {
  ASSERT_NO_FATAL_FAILURE(stop_a_run());
  { std::ofstream(work("hand.csv")) << "precious"; }
  expect_refused(work("hand.csv") + ": exists");
  EXPECT_EQ(read_file(work("hand.csv")), "precious");
}

// K30: a file appeared at the finished log's sidecar name since the run stopped.
TEST_F(RestartLeavesTheLogAsItWas, AFileAtTheSidecarsName) {
  ASSERT_NO_FATAL_FAILURE(stop_a_run());
  { std::ofstream(log + ".xdmf") << "precious"; }
  expect_refused(log + ".xdmf: exists");
  EXPECT_EQ(read_file(log + ".xdmf"), "precious");
}

using RestartFromAnotherFolder = Cli;

// K25: a run started in one folder, with a recorded trajectory and a recording given relative to
// it, continued from another folder: both resolve where the run started.
TEST_F(RestartFromAnotherFolder, FindsTheRunsRelativeFiles) {
  const std::filesystem::path folder = work_.path() / "started_here";
  std::filesystem::create_directory(folder);
  const auto in_folder = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv{MSSPH_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
  };
  // A recording to replay, then the scene that replays it, next to each other.
  ASSERT_EQ(run_process(in_folder({"run", kTinyDrop, "--out", "first.h5", "-q", "--record-device", "hand.csv", "--set",
                                   "simulation/duration=0.05"}),
                        folder)
                .exit_code,
            0);
  nlohmann::json scene = read_json(kTinyDrop);
  scene["proxy"]["trajectory"] = {{"source", "recorded"}, {"file", "hand.csv"}};
  std::ofstream(folder / "scene.json") << scene.dump(2);
  ChildProcess run(in_folder({"run", "scene.json", "--backend", "cpu", "--threads", "1", "--out", "replay.h5",
                              "--record-device", "again.csv", "--set", "simulation/duration=2"}),
                   folder, capture_.path());
  ASSERT_TRUE(wait_for([&] { return non_empty_file((folder / "replay.h5.partial").string()); }, 60s));
  run.send(SIGTERM);
  ASSERT_EQ(run.wait().exit_code, 143) << "the run ended before the signal?";
  const ProcessResult continued = mssph({"run", "--restart", "started_here/replay.h5.partial", "-q"});
  EXPECT_EQ(continued.exit_code, 0) << continued.err;
  EXPECT_EQ(status_of((folder / "replay.h5").string()), "completed");
  EXPECT_TRUE(std::filesystem::is_regular_file(folder / "again.csv")) << "the recording lands where it was asked";
  EXPECT_FALSE(std::filesystem::exists(work("again.csv")));
}

}  // namespace
}  // namespace mssph::test
