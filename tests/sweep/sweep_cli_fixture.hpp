#pragma once
// Runs `mssph sweep` on the tiny sweeps of tests/data/sweeps in a fresh working directory, and
// reads back what it wrote: the manifest, each point's log and the summary.
#include "../cli/cli_fixture.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <optional>
#include <sstream>

namespace mssph::test {

inline std::string tiny_product_sweep() { return data_file("sweeps/tiny_product.json"); }

class SweepCli : public Cli {
 protected:
  // One OpenMP thread per point: the tiny test scenes gain nothing from more, and on a shared
  // machine two spinning threads per point make test times swing by two orders of magnitude.
  SweepCli() {
    if (const char* previous = std::getenv("OMP_NUM_THREADS")) previous_threads_ = previous;
    setenv("OMP_NUM_THREADS", "1", 1);
  }
  ~SweepCli() override {
    if (previous_threads_) {
      setenv("OMP_NUM_THREADS", previous_threads_->c_str(), 1);
    } else {
      unsetenv("OMP_NUM_THREADS");
    }
  }
  std::optional<std::string> previous_threads_;

  // As Cli::mssph, with room for a sweep of several runs on a busy machine.
  ProcessResult mssph(const std::vector<std::string>& args) const {
    return start(args)->wait(std::chrono::minutes(10));
  }

  std::string out() const { return work("sweep_out"); }
  nlohmann::json manifest() const { return read_json(out() + "/sweep.json"); }
  std::string log_of(const nlohmann::json& point) const { return out() + "/" + point["log"].get<std::string>(); }
  std::string log_of(std::size_t index) const { return log_of(manifest()["points"][index]); }
  // mssph run publishes a log under its name only once completed; until then, and after a failure
  // or an interruption, it is <log>.partial. The point's log as it is on disk now:
  std::string log_on_disk(std::size_t index) const {
    const std::string published = log_of(index);
    return std::filesystem::exists(published) ? published : published + ".partial";
  }
  bool log_exists(std::size_t index) const { return std::filesystem::exists(log_on_disk(index)); }

  // A file's inode: a rerun point's log is a new file (created, then renamed over the old one).
  static ino_t inode(const std::string& path) {
    struct stat s {};
    return stat(path.c_str(), &s) == 0 ? s.st_ino : 0;
  }

  // summary.csv as rows of cells (header first); a quoted cell may hold commas and "" for ".
  std::vector<std::vector<std::string>> summary_csv() const {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row;
    std::string cell;
    bool quoted = false;
    const std::string text = read_file(out() + "/summary.csv");
    for (std::size_t i = 0; i < text.size(); ++i) {
      const char c = text[i];
      if (quoted) {
        if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
          cell += '"';
          ++i;
        } else if (c == '"') {
          quoted = false;
        } else {
          cell += c;
        }
      } else if (c == '"') {
        quoted = true;
      } else if (c == ',' || c == '\n') {
        row.push_back(cell);
        cell.clear();
        if (c == '\n') {
          rows.push_back(row);
          row.clear();
        }
      } else {
        cell += c;
      }
    }
    return rows;
  }
  // The column of summary.csv named `name`, without the header.
  std::vector<std::string> csv_column(const std::string& name) const {
    const auto rows = summary_csv();
    const auto at = std::find(rows.at(0).begin(), rows.at(0).end(), name);
    EXPECT_NE(at, rows.at(0).end()) << "no column " << name;
    std::vector<std::string> column;
    for (std::size_t r = 1; r < rows.size(); ++r)
      column.push_back(rows[r].at(static_cast<std::size_t>(at - rows[0].begin())));
    return column;
  }
};

}  // namespace mssph::test
