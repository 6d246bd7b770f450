// Figure 3 at coarse resolution (4 cm spacing, the README's first command) on the cpu backend:
// every shape check of scripts/figures/figure3_checks.py passes on the real runs. The checks'
// expectations (Archimedes, Hertz, weight, the rigid impact as the reference) are physical; the
// checks' ability to fail is tested on wrong curves in figure3_checks_test.py.
#include "cli_fixture.hpp"

namespace mssph::test {
namespace {

using Figure3Physics = Cli;

TEST_F(Figure3Physics, CoarseDropsPassEveryShapeCheck) {
  // Minutes of simulation on 2 busy CPU cores: far past run_process's one-minute limit.
  const ProcessResult r = start({"figure", "3", "--backend", "cpu", "--resolution", "coarse", "--configs",
                                 MSSPH_SOURCE_DIR "/configs", "--out", work("fig3"), "-q"})
                              ->wait(std::chrono::minutes(15));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json report = read_json(work("fig3/figure3_checks.json"));
  EXPECT_GE(report["checks"].size(), 14u);
  for (const nlohmann::json& c : report["checks"]) {
    EXPECT_TRUE(c["passed"].get<bool>()) << c.dump(2);
  }
}

}  // namespace
}  // namespace mssph::test
