// The XDMF sidecar that lets ParaView open snapshots: valid XML whose every data item names a
// dataset of the run log with the stated dimensions and type (checked by check_xdmf.py).
#include "child_process.hpp"
#include "io/run_log.hpp"
#include "python_tools.hpp"
#include "run_log_samples.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace mssph::test {
namespace {

void add_snapshot(RunLog& log, long long step, std::size_t particles) {
  const std::vector<float> vectors(3 * particles, 0.5f), scalars(particles, 1000.0f);
  log.add_snapshot(step, 0.001 * static_cast<double>(step), SnapshotFields{vectors, vectors, scalars, scalars});
}

TEST(XdmfSidecar, ListsEverySnapshotWithTheBodyIndex) {
  const TempDir dir;
  const std::string path = (dir / "snapshots.h5").string();
  {
    RunLog log(path, sample_metadata());
    log.write_array("/particles/body", std::vector<int>{0, 0, 1, 1}, "1", "body index");
    add_snapshot(log, 0, 4);
    add_snapshot(log, 25, 4);
    add_snapshot(log, 50, 4);
    log.finish_completed();
  }
  const ProcessResult check = check_xdmf(path + ".xdmf");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("grids 3"), std::string::npos) << check.out;
  EXPECT_NE(read_file(path + ".xdmf").find("/particles/body"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path + ".xdmf.partial"));
}

TEST(XdmfSidecar, OmitsTheBodyIndexWhenTheLogHasNone) {
  const TempDir dir;
  const std::string path = (dir / "no_bodies.h5").string();
  {
    RunLog log(path, sample_metadata());
    add_snapshot(log, 0, 3);
  }
  const ProcessResult check = check_xdmf(path + ".partial.xdmf");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_EQ(read_file(path + ".partial.xdmf").find("/particles/body"), std::string::npos);
}

TEST(XdmfSidecar, OmitsTheBodyIndexOfAnotherLength) {
  const TempDir dir;
  const std::string path = (dir / "other_length.h5").string();
  {
    RunLog log(path, sample_metadata());
    log.write_array("/particles/body", std::vector<int>{0, 1}, "1", "body index");
    add_snapshot(log, 0, 3);
  }
  const ProcessResult check = check_xdmf(path + ".partial.xdmf");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST(XdmfSidecar, AFileNameWithXmlSpecialCharactersStaysValid) {
  const TempDir dir;
  const std::string path = (dir / "drop & <stir> \"v2\".h5").string();
  {
    RunLog log(path, sample_metadata());
    add_snapshot(log, 0, 2);
  }
  const ProcessResult check = check_xdmf(path + ".partial.xdmf");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

// An unfinished log's sidecar lies next to it, under the partial name, and names that file.
TEST(XdmfSidecar, AnUnfinishedLogsSidecarNamesThePartialFile) {
  const TempDir dir;
  const std::string path = (dir / "unfinished.h5").string();
  {
    RunLog log(path, sample_metadata());
    add_snapshot(log, 0, 2);
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".xdmf"));
  EXPECT_NE(read_file(path + ".partial.xdmf").find("unfinished.h5.partial:"), std::string::npos);
}

TEST(XdmfSidecar, ReplacingALogRemovesItsSidecar) {
  const TempDir dir;
  const std::string path = (dir / "replaced.h5").string();
  {
    RunLog first(path, sample_metadata());
    add_snapshot(first, 0, 2);
    first.finish_completed();
  }
  ASSERT_TRUE(std::filesystem::exists(path + ".xdmf"));
  EXPECT_FALSE(std::filesystem::exists(path + ".partial.xdmf"));
  RunLog second(path, sample_metadata(), /*replace=*/true);
  second.finish_completed();
  EXPECT_FALSE(std::filesystem::exists(path + ".xdmf")) << "it would name snapshots the new file lacks";
}

}  // namespace
}  // namespace mssph::test
