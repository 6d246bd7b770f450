#include "sweep/point_runner.hpp"

#include "run/interrupt.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <optional>
#include <thread>

extern char** environ;

namespace mssph::sweep {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kPollInterval = std::chrono::milliseconds(50);

struct Running {
  pid_t pid = -1;
  std::size_t task = 0;
  std::size_t slot = 0;
  Clock::time_point start;
};

// In the child between fork and exec only async-signal-safe calls are allowed, so everything it
// needs is prepared here.
struct PreparedChild {
  std::vector<std::string> argv_storage;
  std::vector<char*> argv;
  std::vector<std::string> environment_storage;
  std::vector<char*> environment;
  std::string output_path;
};

// This process's environment with the slot's NAME=VALUE entries replacing those of the same name.
std::vector<std::string> child_environment(const std::vector<std::string>& changes) {
  std::vector<std::string> out;
  const auto name_of = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const std::string& c : changes) replaced = replaced || name_of(c) == name_of(entry);
    if (!replaced) out.push_back(entry);
  }
  out.insert(out.end(), changes.begin(), changes.end());
  return out;
}

[[noreturn]] void exec_child(const PreparedChild& child, pid_t parent) {
  // Die with the sweep: a killed sweep must not leave points running that nobody waits for.
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(127);  // the parent died before prctl took effect
  const int fd = open(child.output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  // The child handles SIGINT/SIGTERM itself (its log says "interrupted"), whatever the parent did.
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  execve(child.argv[0], child.argv.data(), child.environment.data());
  const char message[] = "mssph sweep: cannot start the point's run (execve failed)\n";
  [[maybe_unused]] const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(127);
}

pid_t start_child(const PointTask& task, const RunSlot& slot) {
  PreparedChild child;
  child.argv_storage = task.argv;
  for (std::string& a : child.argv_storage) child.argv.push_back(a.data());
  child.argv.push_back(nullptr);
  child.environment_storage = child_environment(slot.environment);
  for (std::string& e : child.environment_storage) child.environment.push_back(e.data());
  child.environment.push_back(nullptr);
  child.output_path = task.output_path;
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) exec_child(child, parent);
  return pid;
}

// "exit code 1", "signal 9 (Killed)"
std::string describe_wait_status(int status) {
  if (WIFSIGNALED(status)) {
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  }
  return "exit code " + std::to_string(WEXITSTATUS(status));
}

std::string indent(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    out += "    " + text.substr(start, end == std::string::npos ? std::string::npos : end - start) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

std::string tail_of_file(const std::string& path, std::size_t lines) {
  std::ifstream in(path);
  std::deque<std::string> last;
  for (std::string line; std::getline(in, line);) {
    last.push_back(line);
    if (last.size() > lines) last.pop_front();
  }
  std::string out;
  for (const std::string& line : last) out += line + "\n";
  return out;
}

RunnerReport run_point_tasks(const std::vector<PointTask>& tasks, const std::vector<RunSlot>& slots,
                             SweepProgress& progress) {
  RunnerReport report;
  install_interrupt_handlers();
  std::vector<std::optional<Running>> busy(slots.size());
  std::size_t next = 0;
  bool stopping = false;
  const auto running_count = [&] {
    std::size_t n = 0;
    for (const auto& b : busy) n += b ? 1 : 0;
    return n;
  };
  const auto stop_all = [&](int signal_number) {
    stopping = true;
    for (const auto& b : busy) {
      if (b) kill(b->pid, signal_number);
    }
  };

  while (true) {
    if (interrupt_requested() && !report.stopped_by_signal) {
      report.stopped_by_signal = true;
      progress.note("interrupted: passing the signal on to " + std::to_string(running_count()) +
                    " running point(s) and starting no more");
      stop_all(SIGTERM);
    }
    for (std::size_t s = 0; s < slots.size() && !stopping && next < tasks.size(); ++s) {
      if (busy[s]) continue;
      const PointTask& task = tasks[next];
      const pid_t pid = start_child(task, slots[s]);
      if (pid < 0) {
        report.bad_input = "cannot start a process for " + task.label + ": " + std::strerror(errno);
        stop_all(SIGTERM);
        break;
      }
      busy[s] = Running{pid, next, s, Clock::now()};
      ++next;
      progress.counts().running = running_count();
      progress.started(task.label + (slots.size() > 1 ? " on " + slots[s].label : ""));
    }
    if (running_count() == 0 && (stopping || next >= tasks.size())) break;

    bool reaped = false;
    for (auto& b : busy) {
      if (!b) continue;
      int status = 0;
      const pid_t done = waitpid(b->pid, &status, WNOHANG);
      if (done == 0 || (done < 0 && errno == EINTR)) continue;
      reaped = true;
      const PointTask& task = tasks[b->task];
      const double seconds = std::chrono::duration<double>(Clock::now() - b->start).count();
      const PointStatus log = read_point_status(task.log_path, task.point_hash);
      SweepCounts& counts = progress.counts();
      b.reset();
      counts.running = running_count();
      std::string what = task.label;
      if (log.state == PointState::completed) {
        ++report.completed;
        ++counts.done;
        what += " completed";
      } else if (log.state == PointState::failed) {
        ++report.failed;
        ++counts.failed;
        what += " FAILED (" + log.status + "); its output " + task.output_path + " ends:\n" +
                indent(tail_of_file(task.output_path, 5));
      } else if (log.state == PointState::busy) {
        // Another run took the log first (another sweep on the same --out): not this input's fault.
        ++report.interrupted;
        ++counts.interrupted;
        what += " did not start: " + log.status + "; it runs when the sweep is resumed after that run";
      } else if (done > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 2) {
        // The run rejected its input although the scene loader accepted the point (a backend
        // this build lacks, a scene the particle builder rejects): every point would.
        report.bad_input = task.label + ": mssph run rejected its input:\n" + indent(tail_of_file(task.output_path, 5));
        stop_all(SIGTERM);
        what += " rejected its input";
      } else {
        ++report.interrupted;
        ++counts.interrupted;
        what += " did not complete (" + (done > 0 ? describe_wait_status(status) : std::string("lost")) + ", log " +
                (log.state == PointState::missing ? std::string("missing") : "\"" + log.status + "\"") +
                "); it runs again when the sweep is resumed";
      }
      progress.finished(what, seconds);
    }
    if (!reaped) {
      progress.tick();
      std::this_thread::sleep_for(kPollInterval);
    }
  }
  return report;
}

}  // namespace mssph::sweep
