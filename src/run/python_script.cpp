#include "python_script.hpp"

#include "util/child_process.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

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

void check_plotting_python() {
  // Prints the modules it cannot find, one line, and exits 1 when there are any.
  const std::string probe =
      "import importlib.util, sys\n"
      "missing = [m for m in ('h5py', 'numpy', 'matplotlib') if importlib.util.find_spec(m) is None]\n"
      "print(', '.join(missing))\n"
      "sys.exit(1 if missing else 0)\n";
  std::string missing;
  const int code = run_program({python_interpreter(), "-c", probe}, &missing);
  if (code == 0) return;
  while (!missing.empty() && (missing.back() == '\n' || missing.back() == ' ')) missing.pop_back();
  const std::string what = code == 1 && !missing.empty()
                               ? python_interpreter() + " cannot import " + missing
                               : python_interpreter() + " did not run (exit code " + std::to_string(code) + ")";
  throw std::runtime_error(what +
                           "; the plots and reports need Python 3 with h5py, NumPy and matplotlib (on Debian: "
                           "apt-get install python3-h5py python3-numpy python3-matplotlib), or MSSPH_PYTHON naming "
                           "an interpreter that has them. Nothing was run.");
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
