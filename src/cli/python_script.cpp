#include "python_script.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstdio>

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

int run_python_script(const std::string& relative, const std::vector<std::string>& arguments) {
  std::vector<std::string> argv{python_interpreter(), python_script_path(relative)};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::vector<char*> c_argv;
  for (std::string& a : argv) c_argv.push_back(a.data());
  c_argv.push_back(nullptr);
  // What this process printed must appear before what the script prints.
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = 0;
  if (posix_spawn(&pid, c_argv[0], nullptr, nullptr, c_argv.data(), environ) != 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace mssph::cli
