#include "python_script.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>

extern char** environ;

namespace mssph::cli {

std::string python_interpreter() {
  if (const char* env = std::getenv("MSSPH_PYTHON"); env && *env) return env;
  return MSSPH_PYTHON;
}

std::string python_script_path(const std::string& relative) {
  const char* env = std::getenv("MSSPH_SCRIPTS_DIR");
  const std::string folder = env && *env ? std::string(env) : std::string(MSSPH_SOURCE_DIR) + "/scripts";
  return folder + "/" + relative;
}

namespace {

// Starts the script; with `stdout_pipe` its stdout goes to that pipe's write end.
int spawn_python_script(const std::string& relative, const std::vector<std::string>& arguments, const int* stdout_pipe,
                        pid_t& pid) {
  std::vector<std::string> argv{python_interpreter(), python_script_path(relative)};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::vector<char*> c_argv;
  for (std::string& a : argv) c_argv.push_back(a.data());
  c_argv.push_back(nullptr);
  // What this process printed must appear before what the script prints.
  std::fflush(stdout);
  std::fflush(stderr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdout_pipe) {
    posix_spawn_file_actions_adddup2(&actions, stdout_pipe[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, stdout_pipe[0]);
    posix_spawn_file_actions_addclose(&actions, stdout_pipe[1]);
  }
  const int result = posix_spawn(&pid, c_argv[0], &actions, nullptr, c_argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return result;
}

int wait_for_script(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace

int run_python_script_capturing(const std::string& relative, const std::vector<std::string>& arguments,
                                std::string& output) {
  int fds[2];
  if (pipe(fds) != 0) return 127;
  pid_t pid = 0;
  const int spawned = spawn_python_script(relative, arguments, fds, pid);
  close(fds[1]);
  if (spawned != 0) {
    close(fds[0]);
    return 127;
  }
  output.clear();
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    output.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  return wait_for_script(pid);
}

int run_python_script(const std::string& relative, const std::vector<std::string>& arguments) {
  pid_t pid = 0;
  if (spawn_python_script(relative, arguments, nullptr, pid) != 0) return 127;
  return wait_for_script(pid);
}

}  // namespace mssph::cli
