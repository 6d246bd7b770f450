// `mssph figure tss` on the cpu backend: the proxy taps the bone, squeezes the organ and stirs the
// blood in that order, each phase's push shows in the body touched (Newton's third law) and not in
// the others, and the device renders within its limits. The checks' measurements are in
// scripts/figures/tss.py; with the bone's contact left undamped (viscosity 5 Pa s) its rattle on
// the ground fails them, so they can fail.
#include "cli_fixture.hpp"

namespace mssph::test {
namespace {

using FigureTssPhysics = Cli;

TEST_F(FigureTssPhysics, EachPhaseTouchesItsBodyWithinTheDeviceLimits) {
  // Minutes of simulation on 2 busy CPU cores: far past run_process's one-minute limit.
  const ProcessResult r = start({"figure", "tss", "--backend", "cpu", "--scene",
                                 MSSPH_SOURCE_DIR "/configs/tap_squeeze_stir.json", "--out", work("tss"), "-q"})
                              ->wait(std::chrono::minutes(15));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json report = read_json(work("tss/tss_checks.json"));
  ASSERT_EQ(report["phases"].size(), 3u);
  EXPECT_EQ(report["phases"][0]["body"], "bone");
  EXPECT_EQ(report["phases"][1]["body"], "organ");
  EXPECT_EQ(report["phases"][2]["body"], "blood");
  for (const nlohmann::json& c : report["checks"]) EXPECT_TRUE(c["passed"].get<bool>()) << c.dump(2);
  EXPECT_TRUE(std::filesystem::is_regular_file(work("tss/tss.png")));
}

}  // namespace
}  // namespace mssph::test
