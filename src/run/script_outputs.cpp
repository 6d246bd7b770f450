#include "script_outputs.hpp"

#include "io/output_claim.hpp"
#include "io/output_file.hpp"
#include "python_script.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace mssph::cli {

void check_script_outputs(const std::string& out, const std::vector<std::string>& names, bool replace) {
  for (const std::string& name : names)
    check_output_file("--out", (std::filesystem::path(out) / name).string(), replace);
  check_python_modules(kPlottingModules);
}

int run_python_script_into(const std::string& relative,
                           const std::function<std::vector<std::string>(const std::string& folder)>& arguments,
                           const std::string& out, bool replace) {
  namespace fs = std::filesystem;
  std::string folder = (fs::path(out) / "drawn.tmp-XXXXXX").string();
  if (mkdtemp(folder.data()) == nullptr) {
    throw std::runtime_error("cannot create a folder like " + folder + ": " + std::strerror(errno));
  }
  const int status = run_python_script(relative, arguments(folder));
  std::string refused;
  std::string moved;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::string target = (fs::path(out) / name).string();
    const std::string why = rename_into_place(entry.path().string(), target, replace);
    if (why.empty()) {
      moved += (moved.empty() ? "" : ", ") + name;
    } else {
      refused += (refused.empty() ? "" : "; ") + target + " " + why;
    }
  }
  if (!moved.empty()) std::printf("%s: moved into %s: %s\n", relative.c_str(), out.c_str(), moved.c_str());
  std::fflush(stdout);
  if (!refused.empty()) {
    throw std::runtime_error(refused + (replace ? "" : " (pass --force to replace files)") + "; what " + relative +
                             " drew for them is kept in " + folder);
  }
  fs::remove(folder);
  return status;
}

}  // namespace mssph::cli
