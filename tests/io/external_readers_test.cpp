// Run logs as other tools see them: h5py (what analysis and plotting scripts use) and h5dump.
#include "child_process.hpp"
#include "io/run_log.hpp"
#include "python_tools.hpp"
#include "run_log_samples.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

namespace mssph::test {
namespace {

constexpr std::size_t kRows = RunLog::kBufferedRows + 3;  // one flushed buffer and a partial one

std::string write_log(const TempDir& dir) {
  const std::string path = (dir / "readers.h5").string();
  RunLog log(path, sample_metadata());
  log.set_attribute("/timing", "phase_names", std::vector<std::string>{"neighbours", "forces"});
  const std::size_t time = log.add_series("/time", 1, "s", "simulated time");
  const std::size_t com = log.add_series("/bodies/ball/centre_of_mass", 3, "m", "centre of mass", {"x", "y", "z"});
  for (std::size_t i = 0; i < kRows; ++i) {
    const double t = scalar_row(i);
    log.append(time, std::span<const double>(&t, 1));
    log.append(com, vector_row(i));
  }
  log.finish_failed("interrupted by a signal");
  return log.path();  // a failed run's log keeps its partial name
}

TEST(ExternalReaders, H5pyReadsAttributesAndSeries) {
  const TempDir dir;
  const std::string path = write_log(dir);
  const nlohmann::json summary = h5py_summary(path);
  ASSERT_TRUE(summary.contains("objects"));
  const RunMetadata m = sample_metadata();
  const nlohmann::json& root = summary["attributes"];
  EXPECT_EQ(root["config"], m.config_json);
  EXPECT_EQ(root["config_file"], m.config_file);
  EXPECT_EQ(root["git_commit"], m.git_commit);
  EXPECT_EQ(root["seed"], m.seed);
  EXPECT_EQ(root["status"], "failed: interrupted by a signal");
  EXPECT_EQ(summary["objects"]["/timing"]["attributes"]["phase_names"], (nlohmann::json{"neighbours", "forces"}));

  const nlohmann::json& time = summary["objects"]["/time"];
  EXPECT_EQ(time["shape"], nlohmann::json{kRows});
  EXPECT_EQ(time["dtype"], "float64");
  EXPECT_EQ(time["attributes"]["units"], "s");
  const nlohmann::json& com = summary["objects"]["/bodies/ball/centre_of_mass"];
  EXPECT_EQ(com["shape"], (nlohmann::json{kRows, 3}));
  EXPECT_EQ(com["attributes"]["units"], "m");
  EXPECT_EQ(com["attributes"]["columns"], (nlohmann::json{"x", "y", "z"}));
  // JSON carries doubles through Python's repr, which round-trips exactly.
  for (std::size_t i = 0; i < kRows; ++i) {
    ASSERT_EQ(time["data"][i].get<double>(), scalar_row(i)) << "row " << i;
    ASSERT_EQ(com["data"][3 * i + 2].get<double>(), vector_row(i)[2]) << "row " << i;
  }
}

TEST(ExternalReaders, H5dumpReadsTheHeader) {
  if (std::string(MSSPH_H5DUMP).empty()) GTEST_SKIP() << "h5dump is not installed (Debian package hdf5-tools)";
  const TempDir dir;
  const std::string path = write_log(dir);
  const ProcessResult dump = run_process({MSSPH_H5DUMP, "-H", path});
  EXPECT_EQ(dump.exit_code, 0) << dump.err;
  for (const char* name : {"DATASET \"time\"", "DATASET \"centre_of_mass\"", "ATTRIBUTE \"status\""}) {
    EXPECT_NE(dump.out.find(name), std::string::npos) << name << " missing from\n" << dump.out;
  }
}

}  // namespace
}  // namespace mssph::test
