#include "util/child_process.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

extern char** environ;

namespace mssph {
namespace {

// Starts the program; with `stdout_pipe` its stdout goes to that pipe's write end.
int spawn(const std::vector<std::string>& argv, const int* stdout_pipe, pid_t& pid) {
  std::vector<std::string> copy = argv;
  std::vector<char*> c_argv;
  for (std::string& a : copy) c_argv.push_back(a.data());
  c_argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdout_pipe) {
    posix_spawn_file_actions_adddup2(&actions, stdout_pipe[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, stdout_pipe[0]);
    posix_spawn_file_actions_addclose(&actions, stdout_pipe[1]);
  }
  const int result = posix_spawnp(&pid, c_argv[0], &actions, nullptr, c_argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return result;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

void read_all(int fd, std::string& output) {
  output.clear();
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    output.append(buffer, static_cast<std::size_t>(n));
  }
}

}  // namespace

int run_program(const std::vector<std::string>& argv, std::string* captured_stdout) {
  if (argv.empty()) return 127;
  pid_t pid = 0;
  if (!captured_stdout) return spawn(argv, nullptr, pid) == 0 ? wait_for(pid) : 127;
  int fds[2];
  if (pipe(fds) != 0) return 127;
  const int spawned = spawn(argv, fds, pid);
  close(fds[1]);
  if (spawned == 0) read_all(fds[0], *captured_stdout);
  close(fds[0]);
  return spawned == 0 ? wait_for(pid) : 127;
}

}  // namespace mssph
