// The shipped sweeps: every point of each is accepted by the scene loader at full resolution, and
// each runs end to end coarse (the --set documented in configs/README.md).
#include "sweep_cli_fixture.hpp"

#include <gmock/gmock.h>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

class ShippedSweeps : public SweepCli, public ::testing::WithParamInterface<const char*> {
 protected:
  std::string file() const { return MSSPH_SOURCE_DIR "/configs/" + std::string(GetParam()); }
};

TEST_P(ShippedSweeps, EveryPointIsAValidScene) {
  const ProcessResult r = mssph({"sweep", file(), "--out", out(), "--dry-run"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("15 points"));
  EXPECT_TRUE(work_entries().empty());
}

TEST_P(ShippedSweeps, RunsCoarseEndToEnd) {
  const ProcessResult r = mssph({"sweep", file(), "--out", out(), "--backend", "cpu", "--jobs", "2", "--set",
                                 "simulation/particle_spacing=0.04", "--set", "simulation/duration=0.02"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(csv_column("state"), std::vector<std::string>(15, "completed"));
  EXPECT_EQ(csv_column("final_status"), std::vector<std::string>(15, "completed"));
  const ProcessResult plot = mssph({"sweep", "plot", out(), "--metric", "peak_rendered_force"});
  EXPECT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_TRUE(std::filesystem::exists(out() + "/plots/peak_rendered_force.svg"));
}

INSTANTIATE_TEST_SUITE_P(Configs, ShippedSweeps, ::testing::Values("sweep_stiffness.json", "sweep_viscosity.json"),
                         [](const auto& test_info) {
                           return std::string(test_info.param).substr(6, std::string(test_info.param).size() - 11);
                         });

}  // namespace
}  // namespace mssph::test
