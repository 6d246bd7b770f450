#pragma once
// Helpers shared by the scene-contract tests.
#include "util/errors.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>

#include <unistd.h>

namespace mssph::test {

// The message of the InputError that `action` throws; a test failure (and "") if it throws none.
template <class Action>
std::string input_error_of(Action&& action) {
  try {
    std::forward<Action>(action)();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError, none was thrown";
  return "";
}

// A file holding `text` in a folder of this process's own (ctest runs test processes in
// parallel, and other builds may run the same tests), removed with the object.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : folder_(std::filesystem::path(testing::TempDir()) / ("mssph_config_tests_" + std::to_string(::getpid()))),
        path_((folder_ / name).string()) {
    std::filesystem::create_directories(folder_);
    std::ofstream(path_) << text;
  }
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    std::filesystem::remove(folder_, ignored);  // only succeeds once the folder is empty
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::filesystem::path folder_;
  std::string path_;
};

inline nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  return nlohmann::json::parse(in);
}

}  // namespace mssph::test
