#pragma once
// Runs a program as a child process with its stdout and stderr captured in files, so tests can
// drive the mssph binary, Python and h5dump, signal them mid-run and read what they printed.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace mssph::test {

struct ProcessResult {
  int exit_code = -1;  // -1 when the process ended by a signal
  int signal = 0;      // the signal that ended it, 0 when it exited
  bool timed_out = false;
  std::string out;  // stdout
  std::string err;  // stderr
};

class ChildProcess {
 public:
  // Starts argv[0] (a path) with the arguments argv[1...] in the working directory `cwd`; stdout
  // and stderr go to files in `capture_dir`, which must exist.
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
               const std::filesystem::path& capture_dir);
  // Kills and reaps a child that is still running, so no test leaves a process behind.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool running();
  void send(int signal_number);
  std::string stderr_so_far() const;
  // Waits for the child to end; past `limit` it is killed and the result says timed_out.
  ProcessResult wait(std::chrono::milliseconds limit = std::chrono::seconds(60));

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  bool reaped_ = false;
  std::filesystem::path out_path_;
  std::filesystem::path err_path_;
};

// Starts, waits and returns the result; the captured output lives in a temporary directory.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd = ".");

std::string read_file(const std::filesystem::path& path);

}  // namespace mssph::test
