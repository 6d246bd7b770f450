// What `mssph run` never destroys and how it ends when it cannot finish: existing files without
// --force, devices, directories and symbolic links even with it, the run's own inputs, another
// run's output (a lock); a full disk or a file size limit (a clear exit 1, the log kept at its
// partial name); SIGINT and SIGHUP (128 + the signal); a closed stdout (still exit 0). Also
// --dry-run (writes nothing) and --threads (recorded in the log).
#include "cli_fixture.hpp"

#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

const std::string kPoke = MSSPH_SOURCE_DIR "/tests/haptics/data/poke.json";

std::string recorded_trajectory(const std::string& file) {
  return "proxy/trajectory=" + nlohmann::json{{"source", "recorded"}, {"file", file}}.dump();
}

using OutputSafety = Cli;

TEST_F(OutputSafety, AnExistingLogIsReplacedOnlyWithForce) {
  const std::string out = work("run.h5");
  ASSERT_EQ(mssph({"run", kTinyDrop, "--out", out, "-q"}).exit_code, 0);
  expect_refused_and_untouched({"run", kTinyDrop, "--out", out, "-q"}, out, "exists; pass --force");
  const ProcessResult forced = mssph({"run", kTinyDrop, "--out", out, "-q", "--force"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(status_of(out), "completed");
  EXPECT_EQ(work_entries(), std::vector<std::string>{"run.h5"});
}

TEST_F(OutputSafety, DevicesDirectoriesFifosAndLinksAreNeverReplacedEvenWithForce) {
  std::filesystem::create_directory(work("dir.h5"));
  ASSERT_EQ(mkfifo(work("fifo.h5").c_str(), 0644), 0);
  { std::ofstream(work("target.h5")) << "someone's data"; }
  std::filesystem::create_symlink(work("target.h5"), work("link.h5"));
  if (std::filesystem::exists("/dev/null")) {
    expect_refused_and_untouched({"run", kTinyDrop, "--out", "/dev/null", "--force"}, "/dev/null", "is a device");
  }
  expect_refused_and_untouched({"run", kTinyDrop, "--out", work("dir.h5"), "--force"}, work("dir.h5"), "directory");
  expect_refused_and_untouched({"run", kTinyDrop, "--out", work("fifo.h5"), "--force"}, work("fifo.h5"), "a FIFO");
  expect_refused_and_untouched({"run", kTinyDrop, "--out", work("link.h5"), "--force"}, work("link.h5"),
                               "a symbolic link");
  EXPECT_EQ(read_file(work("target.h5")), "someone's data");
}

TEST_F(OutputSafety, TheRunsInputsAreNeverItsOutputs) {
  const std::string scene = work("scene.json");
  std::filesystem::copy_file(kTinyDrop, scene);
  expect_refused_and_untouched({"run", scene, "--out", scene, "--force"}, scene, "is the scene file");
  // The same file by another name.
  std::filesystem::create_directory(work("sub"));
  expect_refused_and_untouched({"run", scene, "--out", work("sub/../scene.json"), "--force"}, scene,
                               "is the scene file");
  // A recorded trajectory the run replays, given as --record-device.
  const std::string recording = work("hand.csv");
  ASSERT_EQ(mssph({"run", kPoke, "--out", work("first.h5"), "--record-device", recording, "-q", "--set",
                   "simulation/duration=0.05"})
                .exit_code,
            0);
  expect_refused_and_untouched({"run", kPoke, "--out", work("second.h5"), "--set", recorded_trajectory(recording),
                                "--record-device", recording, "--force"},
                               recording, "the scene's recorded trajectory");
  expect_refused_and_untouched(
      {"run", kPoke, "--out", work("third.h5"), "--record-device", work("third.h5"), "--force"}, work("third.h5"),
      "the run writes its log");
}

TEST_F(OutputSafety, ALeftoverPartialLogIsReplacedOnlyWithForce) {
  const std::string out = work("left.h5");
  { std::ofstream(out + ".partial") << "a killed run's log"; }
  expect_refused_and_untouched({"run", kTinyDrop, "--out", out, "-q"}, out + ".partial", "did not finish");
  EXPECT_EQ(mssph({"run", kTinyDrop, "--out", out, "-q", "--force"}).exit_code, 0);
  EXPECT_EQ(status_of(out), "completed");
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

TEST_F(OutputSafety, TwoRunsCannotWriteOnePathAndSigintEndsTheFirstWith130) {
  const std::string out = work("shared.h5");
  const auto first = start({"run", kTinyDrop, "--out", out, "-q", "--set", "simulation/duration=1000"});
  // The partial file is locked once it is a readable log: wait for its first flush.
  ASSERT_TRUE(wait_for(
      [&] { return std::filesystem::exists(out + ".partial") && std::filesystem::file_size(out + ".partial") > 0; },
      60s));
  for (const bool force : {false, true}) {
    std::vector<std::string> args{"run", kTinyDrop, "--out", out, "-q"};
    if (force) args.push_back("--force");
    const ProcessResult second = mssph(args);
    EXPECT_EQ(second.exit_code, 2) << second.err;
    EXPECT_NE(second.err.find("another run is writing it"), std::string::npos) << second.err;
  }
  ASSERT_TRUE(first->running());
  first->send(SIGINT);
  const ProcessResult r = first->wait();
  EXPECT_EQ(r.exit_code, 130) << r.err;
  EXPECT_EQ(status_of(out + ".partial").rfind("interrupted: SIGINT after step ", 0), 0u) << status_of(out + ".partial");
  EXPECT_FALSE(std::filesystem::exists(out));
}

// `--out <another run's out>.partial --force` would rename its log over the file that run holds
// locked: refused, and the other run goes on writing (and finishing) its own log.
TEST_F(OutputSafety, ThePartialFileAnotherRunHoldsIsNeverReplacedEvenWithForce) {
  const std::string out = work("x.h5");
  const auto first = start({"run", kTinyDrop, "--out", out, "-q", "--set", "simulation/duration=1000"});
  ASSERT_TRUE(wait_for([&] { return non_empty_file(out + ".partial"); }, 60s));
  const ProcessResult second = mssph({"run", kTinyDrop, "--out", out + ".partial", "-q", "--force"});
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("--out " + out + ".partial: another run is writing it"), std::string::npos) << second.err;
  EXPECT_FALSE(std::filesystem::exists(out + ".partial.partial"));
  ASSERT_TRUE(first->running());
  first->send(SIGINT);
  const ProcessResult r = first->wait();
  EXPECT_EQ(r.exit_code, 130) << r.err;
  const h5::Handle log = open_read_only(out + ".partial");
  EXPECT_EQ(h5::read_string_attribute(log.id(), "status").rfind("interrupted: SIGINT", 0), 0u);
  EXPECT_NE(h5::read_string_attribute(log.id(), "command_line").find("--out " + out + " "), std::string::npos)
      << "the first run's own log";
}

TEST_F(OutputSafety, SighupEndsTheRunWith129) {
  const std::string out = work("hup.h5");
  const auto run = start({"run", kTinyDrop, "--out", out, "-q", "--set", "simulation/duration=1000"});
  ASSERT_TRUE(wait_for(
      [&] { return std::filesystem::exists(out + ".partial") && std::filesystem::file_size(out + ".partial") > 0; },
      60s));
  run->send(SIGHUP);
  const ProcessResult r = run->wait();
  EXPECT_EQ(r.exit_code, 129) << r.err;
  EXPECT_EQ(status_of(out + ".partial").rfind("interrupted: SIGHUP", 0), 0u) << status_of(out + ".partial");
}

// stdout is a pipe whose reader has gone (`mssph run ... | head -0`): the summary line cannot be
// written, but the run has completed and says so.
TEST_F(OutputSafety, AClosedStdoutDoesNotFailACompletedRun) {
  const std::string out = work("piped.h5");
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    execl(MSSPH_BINARY, MSSPH_BINARY, "run", kTinyDrop.c_str(), "--out", out.c_str(), "-q",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[0]);  // no reader: the child's write to stdout fails (EPIPE, or SIGPIPE if not ignored)
  close(fds[1]);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(status_of(out), "completed");
}

// A full disk, for real: a 1.6 MB tmpfs, which only root may mount.
TEST_F(OutputSafety, ADiskFullRunExitsOneAndKeepsItsPartialLogMarkedFailed) {
  const std::string mount_point = work("small_disk");
  std::filesystem::create_directory(mount_point);
  if (mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=1600k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno)
                 << "); AFileSizeLimitIsAWriteErrorNotACrash injects the failure instead";
  }
  const std::string out = mount_point + "/full.h5";
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", out, "-q", "--set", "output/snapshot_interval=0.0005",
                                 "--set", "simulation/duration=1"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("disk full writing " + out + ".partial"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(status_of(out + ".partial").rfind("failed: disk full writing", 0), 0u) << status_of(out + ".partial");
  umount(mount_point.c_str());
}

// The same failure injected where mounting is not allowed: a file size limit (setrlimit
// RLIMIT_FSIZE, what `ulimit -f` sets) makes writes fail with EFBIG, as a full disk makes them
// fail with ENOSPC, and sends SIGXFSZ, which would kill a process that did not ignore it.
TEST_F(OutputSafety, AFileSizeLimitIsAWriteErrorNotACrash) {
  const std::string out = work("limited.h5");
  const std::string err = work_.path().parent_path() / (work_.path().filename().string() + ".err");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const rlimit limit{2500 * 1024, 2500 * 1024};  // room for the start of the log, not for 2000 snapshots
    setrlimit(RLIMIT_FSIZE, &limit);
    freopen(err.c_str(), "w", stderr);
    execl(MSSPH_BINARY, MSSPH_BINARY, "run", kTinyDrop.c_str(), "--out", out.c_str(), "-q", "--set",
          "output/snapshot_interval=0.0005", "--set", "simulation/duration=1", static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const std::string messages = read_file(err);
  std::filesystem::remove(err);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << messages;
  EXPECT_EQ(WEXITSTATUS(status), 1) << messages;
  EXPECT_NE(messages.find("file size limit (ulimit -f) reached writing " + out + ".partial"), std::string::npos)
      << messages;
  EXPECT_FALSE(std::filesystem::exists(out));
  const std::string status_text = status_of(out + ".partial");
  EXPECT_EQ(status_text.rfind("failed: file size limit", 0), 0u) << status_text;
  // Nothing logged before the failure is lost: the partial log is a readable file with its rows.
  EXPECT_GT(h5::dataset_shape(open_read_only(out + ".partial").id(), "/time").at(0), 0u);
}

TEST_F(OutputSafety, DryRunPrintsThePlanAndWritesNothing) {
  const ProcessResult r = mssph({"run", kTinyDrop, "--dry-run"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // tiny_drop: a 0.5 x 0.5 x 0.1 m ground at 5 cm (10 x 10 x 2 = 200) and the ball's 27.
  for (const char* line : {"particles: 227", "ground (boundary): 200", "ball (rigid): 27", "memory estimate: host",
                           "ball acoustic: ", "steps: 40 ", "threads: "}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " in\n" << r.out;
  }
  EXPECT_TRUE(work_entries().empty()) << "a dry run writes nothing";
}

TEST_F(OutputSafety, ThreadsAreSetAndRecorded) {
  const std::string out = work("threads.h5");
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", out, "--threads", "1"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 threads (--threads)"), std::string::npos) << r.err;
  long long threads = 0;
  const h5::Handle file = open_read_only(out);
  const h5::Handle attribute = h5::attribute(H5Aopen(file.id(), "threads", H5P_DEFAULT), "open threads");
  ASSERT_GE(H5Aread(attribute.id(), H5T_NATIVE_LLONG, &threads), 0);
  EXPECT_EQ(threads, 1);
}

}  // namespace
}  // namespace mssph::test
