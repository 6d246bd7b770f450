#include "python_script.hpp"

#include "util/child_process.hpp"

#include <cstdlib>
#include <cstring>
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

void check_python_modules(const std::vector<std::string>& modules) {
  // Given a marker and module names, imports each module and ends with one line: the marker, then
  // "ok" or the modules that failed to import.
  static constexpr const char* kMarker = "mssph-python-probe: ";
  static constexpr const char* kProbe = R"(import sys
missing = []
for name in sys.argv[2:]:
    try:
        __import__(name)
    except Exception:
        missing.append(name)
print(sys.argv[1] + (", ".join(missing) if missing else "ok"))
)";
  std::vector<std::string> argv{python_interpreter(), "-c", kProbe, kMarker};
  argv.insert(argv.end(), modules.begin(), modules.end());
  std::string output;
  const int code = run_program(argv, &output);
  const std::size_t at = output.rfind(kMarker);
  std::string verdict = at == std::string::npos ? "" : output.substr(at + std::strlen(kMarker));
  verdict = verdict.substr(0, verdict.find('\n'));
  if (code == 0 && verdict == "ok") return;
  std::string wanted;
  for (const std::string& m : modules) wanted += (wanted.empty() ? "" : ", ") + m;
  const std::string what =
      code == 0 && !verdict.empty()
          ? python_interpreter() + " cannot import " + verdict
          : python_interpreter() + " did not run a Python 3 probe (exit code " + std::to_string(code) + ")";
  throw std::runtime_error(what + "; this command's scripts need Python 3 with " + wanted +
                           " (on Debian: apt-get install python3-h5py python3-numpy python3-matplotlib), or "
                           "MSSPH_PYTHON naming an interpreter that has them. Nothing was run.");
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
