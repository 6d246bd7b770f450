#pragma once
// Runs the built mssph binary in a fresh temporary working directory, so default output paths
// land there and "no output was written" means that directory is still empty.
#include "child_process.hpp"
#include "h5_read.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace mssph::test {

// Waits until `ready` holds, checking every few milliseconds; false after `limit`.
template <typename Condition>
bool wait_for(Condition ready, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!ready()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// A scene under tests/data, by absolute path (the binary runs elsewhere).
inline std::string data_file(const std::string& name) { return MSSPH_SOURCE_DIR "/tests/data/" + name; }

// The small sphere drop that most CLI tests run.
inline const std::string kTinyDrop = data_file("tiny_drop.json");

// The valid scene the malformed-input corpus alters (the tiny drop's 227 particles).
inline const std::string kCorpusBase = MSSPH_SOURCE_DIR "/tests/corpus/scenes/ok_base.json";

inline nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(read_file(path)); }

class Cli : public ::testing::Test {
 protected:
  std::string work(const std::string& name) const { return (work_ / name).string(); }

  ProcessResult mssph(const std::vector<std::string>& args) const {
    std::vector<std::string> argv{MSSPH_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv, work_.path());
  }

  // Starts mssph without waiting; stdout and stderr are captured in their own directory.
  std::unique_ptr<ChildProcess> start(const std::vector<std::string>& args) const {
    std::vector<std::string> argv{MSSPH_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return std::make_unique<ChildProcess>(argv, work_.path(), capture_.path());
  }

  // Every path under the working directory, relative to it.
  std::vector<std::string> work_entries() const {
    std::vector<std::string> entries;
    for (const auto& e : std::filesystem::recursive_directory_iterator(work_.path())) {
      entries.push_back(std::filesystem::relative(e.path(), work_.path()).string());
    }
    std::sort(entries.begin(), entries.end());
    return entries;
  }

  std::string status_of(const std::string& h5_path) const {
    return h5::read_string_attribute(open_read_only(h5_path).id(), "status");
  }

  TempDir work_;
  TempDir capture_;
};

}  // namespace mssph::test
