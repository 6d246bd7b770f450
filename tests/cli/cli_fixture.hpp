#pragma once
// Runs the built mssph binary in a fresh temporary working directory, so default output paths
// land there and "no output was written" means that directory is still empty.
#include "child_process.hpp"
#include "h5_read.hpp"
#include "temp_dir.hpp"

#include <sys/stat.h>

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

// Whether a file is at `path` and holds at least one byte: a run's log once it is being written.
inline bool non_empty_file(const std::string& path) {
  std::error_code error;
  return std::filesystem::file_size(path, error) > 0 && !error;
}

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

  // Runs mssph, expects exit 2 with `fragment` on stderr, and `path` afterwards exactly as before
  // (the same inode and mode and, for a regular file, the same contents).
  void expect_refused_and_untouched(const std::vector<std::string>& args, const std::string& path,
                                    const std::string& fragment) const {
    struct stat before {};
    const bool existed = lstat(path.c_str(), &before) == 0;
    const std::string content = existed && S_ISREG(before.st_mode) ? read_file(path) : "";
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << "\"" << fragment << "\" in\n" << r.err;
    struct stat after {};
    ASSERT_EQ(lstat(path.c_str(), &after) == 0, existed) << path;
    if (!existed) return;
    EXPECT_EQ(after.st_ino, before.st_ino) << path << " was replaced";
    EXPECT_EQ(after.st_mode, before.st_mode) << path;
    if (S_ISREG(before.st_mode)) {
      EXPECT_EQ(read_file(path), content) << path;
    }
  }

  std::string status_of(const std::string& h5_path) const {
    return h5::read_string_attribute(open_read_only(h5_path).id(), "status");
  }

  TempDir work_;
  TempDir capture_;
};

}  // namespace mssph::test
