// The `status` attribute and what a run log holds when its run ends early: finished, abandoned
// (destroyed without finish_*), or killed (no destructor, no close).
#include "h5_read.hpp"
#include "io/run_log.hpp"
#include "python_tools.hpp"
#include "run_log_samples.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <functional>

namespace mssph::test {
namespace {

std::string status_of(const std::string& path) {
  const h5::Handle file = open_read_only(path);
  return h5::read_string_attribute(file.id(), "status");
}

std::size_t rows_of(const std::string& path, const std::string& dataset) {
  const h5::Handle file = open_read_only(path);
  return static_cast<std::size_t>(h5::dataset_shape(file.id(), dataset).at(0));
}

void append_scalars(RunLog& log, std::size_t series, std::size_t first, std::size_t count) {
  for (std::size_t i = first; i < first + count; ++i) {
    const double v = scalar_row(i);
    log.append(series, std::span<const double>(&v, 1));
  }
}

// Ends the process as `kill -9` would: no destructor runs, HDF5 never closes the file, nothing
// reaches it beyond what RunLog has already written. Called while the log is still in scope.
void die_now() { raise(SIGKILL); }

// Runs `body` in a forked child, which must end in die_now().
void run_and_kill(const std::function<void()>& body) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0) << "fork failed";
  if (pid == 0) {
    try {
      body();
    } catch (...) {
      _exit(3);
    }
    _exit(4);  // body returned: its log was destroyed normally, which is not what is under test
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the child ended with exit code " << WEXITSTATUS(status) << " instead of being killed";
}

TEST(RunLogStatus, RunningThenCompleted) {
  const TempDir dir;
  const std::string path = (dir / "completed.h5").string();
  RunLog log(path, sample_metadata());
  // Written under its partial name; the final path holds only a completed log.
  EXPECT_EQ(log.path(), path + ".partial");
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(status_of(log.path()), "running");
  EXPECT_FALSE(has_attribute(open_read_only(log.path()).id(), "end_time"));
  EXPECT_FALSE(log.finished());
  log.finish_completed();
  EXPECT_EQ(log.path(), path);
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  EXPECT_EQ(status_of(path), "completed");
  EXPECT_TRUE(has_attribute(open_read_only(path).id(), "end_time"));
  EXPECT_TRUE(log.finished());
}

TEST(RunLogStatus, RunningThenFailedWithTheReason) {
  const TempDir dir;
  const std::string final_path = (dir / "failed.h5").string();
  const std::string path = final_path + ".partial";  // a failed run's log keeps its partial name
  RunLog log(final_path, sample_metadata());
  EXPECT_EQ(status_of(path), "running");
  EXPECT_FALSE(log.finished());
  log.finish_failed("blow-up at t = 0.25 s: body \"ball\" has non-finite state");
  EXPECT_EQ(status_of(path), "failed: blow-up at t = 0.25 s: body \"ball\" has non-finite state");
  EXPECT_FALSE(std::filesystem::exists(final_path));
  EXPECT_TRUE(has_attribute(open_read_only(path).id(), "end_time"));
  EXPECT_TRUE(log.finished());
}

TEST(RunLogStatus, DestroyedWithoutFinishStaysRunningWithEveryRow) {
  const TempDir dir;
  const std::string final_path = (dir / "abandoned.h5").string();
  const std::string path = final_path + ".partial";
  constexpr std::size_t kRows = RunLog::kBufferedRows + 100;  // a flushed buffer and a pending one
  {
    RunLog log(final_path, sample_metadata());
    append_scalars(log, log.add_series("/time", 1, "s", "simulated time"), 0, kRows);
  }
  EXPECT_EQ(status_of(path), "running");
  EXPECT_EQ(rows_of(path, "/time"), kRows);
  EXPECT_FALSE(has_attribute(open_read_only(path).id(), "end_time"));
}

TEST(RunLogKilled, BeforeAnyFlushTheFileListsEverySeriesEmpty) {
  const TempDir dir;
  const std::string final_path = (dir / "killed_early.h5").string();
  const std::string path = final_path + ".partial";
  run_and_kill([&] {
    RunLog log(final_path, sample_metadata());
    log.write_array("/particles/body", std::vector<int>{0, 1}, "1", "body index");
    const std::size_t time = log.add_series("/time", 1, "s", "simulated time");
    const std::size_t com = log.add_series("/bodies/ball/centre_of_mass", 3, "m", "centre of mass");
    append_scalars(log, time, 0, 10);
    log.append(com, vector_row(0));
    die_now();
  });
  EXPECT_EQ(status_of(path), "running");
  EXPECT_EQ(rows_of(path, "/time"), 0u);
  EXPECT_EQ(rows_of(path, "/bodies/ball/centre_of_mass"), 0u);
  EXPECT_EQ(read_ints(open_read_only(path).id(), "/particles/body"), (std::vector<int>{0, 1}));
  EXPECT_FALSE(std::filesystem::exists(final_path));
  EXPECT_EQ(h5py_summary(path)["attributes"]["status"], "running");
}

TEST(RunLogKilled, KeepsTheRowsOfTheLastFlush) {
  const TempDir dir;
  const std::string final_path = (dir / "killed_after_flush.h5").string();
  const std::string path = final_path + ".partial";
  constexpr std::size_t kFlushed = 10;
  run_and_kill([&] {
    RunLog log(final_path, sample_metadata());
    const std::size_t time = log.add_series("/time", 1, "s", "simulated time");
    append_scalars(log, time, 0, kFlushed);
    log.flush();
    append_scalars(log, time, kFlushed, 7);
    die_now();
  });
  EXPECT_EQ(status_of(path), "running");
  const std::vector<double> values = read_doubles(open_read_only(path).id(), "/time");
  ASSERT_EQ(values.size(), kFlushed);
  for (std::size_t i = 0; i < kFlushed; ++i) EXPECT_EQ(values[i], scalar_row(i)) << "row " << i;
}

TEST(RunLogKilled, AFullBufferReachesTheFileWithoutAnExplicitFlush) {
  const TempDir dir;
  const std::string final_path = (dir / "killed_after_full_buffer.h5").string();
  const std::string path = final_path + ".partial";
  run_and_kill([&] {
    RunLog log(final_path, sample_metadata());
    const std::size_t time = log.add_series("/time", 1, "s", "simulated time");
    const std::size_t com = log.add_series("/bodies/ball/centre_of_mass", 3, "m", "centre of mass");
    for (std::size_t i = 0; i < RunLog::kBufferedRows + 10; ++i) {
      append_scalars(log, time, i, 1);
      log.append(com, vector_row(i));
    }
    die_now();
  });
  // The first buffer to fill flushed every series, so the other one's rows so far are on disk
  // too: all but the row appended after the flush.
  EXPECT_EQ(rows_of(path, "/time"), RunLog::kBufferedRows);
  EXPECT_EQ(rows_of(path, "/bodies/ball/centre_of_mass"), RunLog::kBufferedRows - 1);
  const std::vector<double> values = read_doubles(open_read_only(path).id(), "/time");
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(values[i], scalar_row(i)) << "row " << i;
}

TEST(RunLogCreation, AFailedCreationLeavesNothingBehind) {
  const TempDir dir;
  const std::filesystem::path taken = dir / "taken.h5";
  std::filesystem::create_directory(taken);
  EXPECT_ANY_THROW(RunLog(taken.string(), sample_metadata()));
  EXPECT_FALSE(std::filesystem::exists(taken.string() + ".partial"));
  const std::filesystem::path file = dir / "plain_file";
  { std::ofstream(file) << "not a directory"; }
  EXPECT_ANY_THROW(RunLog((file / "log.h5").string(), sample_metadata()));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 2u) << "only the directory and the file the test made";
}

TEST(RunLogCreation, CreatesMissingParentDirectories) {
  const TempDir dir;
  const std::string path = (dir / "results" / "runs" / "nested.h5").string();
  RunLog(path, sample_metadata()).finish_completed();
  EXPECT_EQ(status_of(path), "completed");
}

}  // namespace
}  // namespace mssph::test
