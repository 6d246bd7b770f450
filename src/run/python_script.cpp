#include "python_script.hpp"

#include "util/child_process.hpp"

#include <cstdlib>

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

int run_python_script_capturing(const std::string& relative, const std::vector<std::string>& arguments,
                                std::string& output) {
  std::vector<std::string> argv{python_interpreter(), python_script_path(relative)};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv, &output);
}

int run_python_script(const std::string& relative, const std::vector<std::string>& arguments) {
  std::vector<std::string> argv{python_interpreter(), python_script_path(relative)};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv);
}

}  // namespace mssph::cli
