#include "output_path.hpp"

#include "util/errors.hpp"

#include <unistd.h>

#include <filesystem>

namespace mssph::cli {
namespace fs = std::filesystem;

std::string default_output_path(const std::string& scene_name, const std::string& backend_name) {
  return "results/runs/" + scene_name + "_" + backend_name + ".h5";
}

void check_output_path(const std::string& path) {
  const auto fail = [&path](const std::string& why) { throw InputError("--out " + path + ": " + why); };
  const fs::path out(path);
  if (path.empty()) fail("expected a file name");
  std::error_code error;
  if (!out.has_filename() || fs::is_directory(out, error)) {
    fail("is a directory; give a file name, e.g. " + (out / "run.h5").lexically_normal().string());
  }
  if (fs::exists(out, error)) {
    if (access(path.c_str(), W_OK) != 0) fail("the existing file is not writable");
    return;
  }
  // The run log creates the missing parents: what matters is the deepest one that exists.
  fs::path existing = out.parent_path();
  while (!existing.empty() && !fs::exists(existing, error)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, error)) fail(existing.string() + " is not a directory");
  // Creating entries needs write and search permission on the directory.
  if (access(existing.c_str(), W_OK | X_OK) != 0) fail("cannot create files in " + existing.string());
}

}  // namespace mssph::cli
