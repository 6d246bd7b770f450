// What `mssph run --record-device FILE` never destroys: the log another run is writing, a file
// that appears at FILE during the run, whatever a name next to FILE leads to; and what a completed
// run says when its recording cannot be written (a full disk).
#include "cli_fixture.hpp"

#include <sys/mount.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <functional>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

class RecordingOutput : public Cli {
 protected:
  // Starts `mssph run` with `args` and waits until it writes its log `log`.
  std::unique_ptr<ChildProcess> start_writing(const std::vector<std::string>& args, const std::string& log) const {
    auto run = start(args);
    EXPECT_TRUE(wait_for([&] { return non_empty_file(log + ".partial"); }, 60s)) << run->stderr_so_far();
    return run;
  }

  // The files of the working directory whose name starts with `prefix`.
  std::vector<std::string> entries_starting(const std::string& prefix) const {
    std::vector<std::string> found;
    for (const std::string& e : work_entries()) {
      if (e.rfind(prefix, 0) == 0) found.push_back(e);
    }
    return found;
  }

  // A run with a recording stopped (SIGSTOP) while `meanwhile` puts something at the recording's
  // name, then let go: it completes, its log is published, its recording is not, and it says
  // where the recording is kept instead.
  void expect_recording_kept_aside(const std::string& recording, const std::function<void()>& meanwhile) {
    const std::string log = work("a.h5");
    auto run = start_writing({"run", kTinyDrop, "--out", log, "-q", "--threads", "1", "--record-device", recording,
                              "--set", "simulation/duration=4"},
                             log);
    ASSERT_TRUE(run->running()) << "the run ended before it could be stopped";
    run->send(SIGSTOP);
    meanwhile();
    const std::string there = read_file(recording);
    run->send(SIGCONT);
    const ProcessResult r = run->wait();
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(recording + " appeared while the run was writing"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(recording), there) << "replaced";
    EXPECT_EQ(status_of(log), "completed");
    const std::string name = fs::path(recording).filename().string();
    const std::vector<std::string> kept = entries_starting(name + ".tmp-");
    ASSERT_EQ(kept.size(), 1u) << r.err;
    EXPECT_NE(r.err.find(work(kept.front())), std::string::npos) << "the message says where it is\n" << r.err;
  }
};

// C05: the recording's name is the log another run is writing.
TEST_F(RecordingOutput, TheLogAnotherRunIsWritingIsRefusedAtOnce) {
  const std::string log = work("a.h5");
  auto first = start_writing({"run", kTinyDrop, "--out", log, "-q", "--set", "simulation/duration=1000"}, log);
  const ProcessResult second = mssph(
      {"run", kTinyDrop, "--out", work("b.h5"), "-q", "--record-device", log, "--set", "simulation/duration=0.01"});
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("--record-device " + log + ": another run is writing it"), std::string::npos) << second.err;
  EXPECT_FALSE(fs::exists(work("b.h5.partial")));
  EXPECT_FALSE(fs::exists(work("b.h5")));
  ASSERT_TRUE(first->running());
  first->send(SIGINT);
  const ProcessResult r = first->wait();
  EXPECT_EQ(r.exit_code, 130) << r.err;
  EXPECT_EQ(status_of(log + ".partial").rfind("interrupted: SIGINT", 0), 0u) << status_of(log + ".partial");
}

// C04: another run completes its log at the recording's name while this run lasts.
TEST_F(RecordingOutput, AnotherRunsLogThatAppearsMeanwhileIsNotReplaced) {
  const std::string recording = work("r.h5");
  expect_recording_kept_aside(recording, [&] {
    const ProcessResult other = mssph({"run", kTinyDrop, "--out", recording, "-q"});
    EXPECT_EQ(other.exit_code, 0) << other.err;
  });
  EXPECT_EQ(status_of(recording), "completed") << "the other run's log";
}

// O25: a user's file appears at the recording's name while the run lasts.
TEST_F(RecordingOutput, AUsersFileThatAppearsMeanwhileIsNotReplaced) {
  const std::string recording = work("r.csv");
  expect_recording_kept_aside(recording, [&] { std::ofstream(recording) << "precious"; });
  EXPECT_EQ(read_file(recording), "precious");
}

// O06, O07, O23, O24: the names the temporaries used to have, next to the recording and the
// sidecars, as links to a victim and as a user's file: none is followed, none replaced.
TEST_F(RecordingOutput, NamesNextToTheOutputsAreNeitherFollowedNorReplaced) {
  { std::ofstream(work("victim.txt")) << "precious"; }
  fs::create_symlink(work("victim.txt"), work("r.csv.partial"));
  fs::create_symlink(work("victim.txt"), work("o.h5.xdmf.partial"));
  { std::ofstream(work("o.h5.partial.xdmf.partial")) << "mine"; }
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", work("o.h5"), "-q", "--record-device", work("r.csv"),
                                 "--set", "output/snapshot_interval=0.01"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(work("victim.txt")), "precious");
  EXPECT_EQ(read_file(work("o.h5.partial.xdmf.partial")), "mine");
  EXPECT_TRUE(fs::is_symlink(work("r.csv.partial")));
  EXPECT_TRUE(fs::is_symlink(work("o.h5.xdmf.partial")));
  EXPECT_EQ(read_file(work("r.csv")).rfind("t,x,y,z,qx,qy,qz,qw\n", 0), 0u);
  EXPECT_NE(read_file(work("o.h5.xdmf")).find("o.h5:/snapshots/"), std::string::npos);
}

// D_rec: the recording's disk is full (a 4 KiB tmpfs, filled; mounting needs root). The
// simulation completed, so its log is published, marked completed; the run exits 1 with the
// system's reason and says what was lost: the recording file, whose poses the log holds.
TEST_F(RecordingOutput, AFullDiskUnderTheRecordingSaysWhatWasLost) {
  const std::string disk = work("full");
  fs::create_directory(disk);
  if (mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=4k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << ")";
  }
  {
    std::ofstream filler(disk + "/filler");
    const std::string block(4096, 'x');
    for (int k = 0; k < 4 && filler; ++k) filler << block << std::flush;
  }
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", work("o.h5"), "-q", "--record-device", disk + "/r.csv"});
  const std::vector<std::string> left = [&] {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(disk)) names.push_back(e.path().filename().string());
    return names;
  }();
  umount(disk.c_str());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(disk + "/r.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/haptics/device/position"), std::string::npos) << "where the poses are\n" << r.err;
  EXPECT_EQ(left, std::vector<std::string>{"filler"}) << "no half-written recording";
  EXPECT_EQ(status_of(work("o.h5")), "completed");
  const std::string noted = h5::read_string_attribute(open_read_only(work("o.h5")).id(), "record_device_error");
  EXPECT_NE(noted.find("No space left on device"), std::string::npos) << noted;
}

}  // namespace
}  // namespace mssph::test
