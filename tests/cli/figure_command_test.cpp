// `mssph figure 2`, `figure 3` and `figure tss` end to end on tiny settings: the files each
// writes, the checks it computes, and its answers to bad arguments.
#include "cli_fixture.hpp"
#include "python_tools.hpp"

#include <filesystem>
#include <fstream>

namespace mssph::test {
namespace {

namespace fs = std::filesystem;

std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

using FigureCommand = Cli;

TEST_F(FigureCommand, Figure2TimesEachMediumAndSizeAndDrawsThem) {
  const ProcessResult r = mssph({"figure", "2", "--backend", "cpu", "--media", "fluid,rigid", "--sizes", "700,1300",
                                 "--min-time", "0.02", "--out", work("fig2")});
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  for (const char* name : {"figure2.h5", "figure2.csv", "figure2.png", "figure2.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(work("fig2/") + name)) << name;
  }
  // Two sizes span less than a decade: no log-log variant.
  EXPECT_FALSE(fs::exists(work("fig2/figure2_loglog.png")));
  // A header and one row per medium and size.
  EXPECT_EQ(line_count(read_file(work("fig2/figure2.csv"))), 1u + 2u * 2u);
  EXPECT_NE(r.out.find("fluid      slope"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("slope ratio"), std::string::npos) << "the paper gives no fluid/rigid ratio:\n" << r.out;

  const h5::Handle file = open_read_only(work("fig2/figure2.h5"));
  EXPECT_EQ(h5::read_string_attribute(file.id(), "status"), "completed");
  EXPECT_EQ(h5::read_string_attribute(file.id(), "backend"), "cpu");
  EXPECT_EQ(h5::read_string_attribute(file.id(), "geometry"), "paper");
  EXPECT_FALSE(h5::read_string_attribute(file.id(), "host_cpu").empty());
  EXPECT_FALSE(h5::read_string_attribute(file.id(), "git_commit").empty());
  // The paper geometry keeps the 2 cm spacing and grows the block: one then two layers of 625.
  EXPECT_EQ(read_doubles(file.id(), "/figure2/fluid/block_particles"), (std::vector<double>{625.0, 1250.0}));
  EXPECT_EQ(read_doubles(file.id(), "/figure2/rigid/spacing"), (std::vector<double>{0.02, 0.02}));
  const std::vector<double> spread = read_doubles(file.id(), "/figure2/fluid/step_time");
  ASSERT_EQ(spread.size(), 6u);  // min, median, max per size
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_GT(spread[3 * k], 0.0);
    EXPECT_LE(spread[3 * k], spread[3 * k + 1]);
    EXPECT_LE(spread[3 * k + 1], spread[3 * k + 2]);
  }
}

TEST_F(FigureCommand, Figure2FixedHeightKeepsTheBlockAndRefinesTheSpacing) {
  const std::vector<std::string> args{"figure",     "2",       "--backend", "cpu",        "--media",
                                      "deformable", "--sizes", "300,2400",  "--geometry", "fixed-height",
                                      "--min-time", "0.02",    "--out",     work("fig2")};
  const ProcessResult r = mssph(args);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  // An earlier figure is replaced only with --force.
  const ProcessResult again = mssph(args);
  EXPECT_EQ(again.exit_code, 2) << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  EXPECT_EQ(mssph(forced).exit_code, 0);
  const h5::Handle file = open_read_only(work("fig2/figure2.h5"));
  EXPECT_EQ(h5::read_string_attribute(file.id(), "geometry"), "fixed-height");
  EXPECT_EQ(read_doubles(file.id(), "/figure2/deformable/height"), (std::vector<double>{0.2, 0.2}));
  const std::vector<double> spacing = read_doubles(file.id(), "/figure2/deformable/spacing");
  ASSERT_EQ(spacing.size(), 2u);
  EXPECT_NEAR(spacing[0] / spacing[1], 2.0, 1e-9) << "8 times the particles, half the spacing";
}

TEST_F(FigureCommand, Figure2RejectsBadArgumentsBeforeTiming) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"--sizes", "2000,300"}, "--sizes: 300: expected particle counts >= 625 with --geometry paper"},
      {{"--sizes", "5000", "--max", "1000"}, "--max 1000: below the largest of --sizes (5000)"},
      {{"--media", "plasma"}, "--media"},
      {{"--geometry", "round"}, "--geometry"},
      {{"--min-time", "0"}, "--min-time: expected a positive number of seconds"},
      // Sizes the machine cannot hold, refused with their estimate before anything is built
      // (std::bad_alloc before; --max near 2^63 overflowed the 1-2-5 loop and never returned).
      {{"--sizes", "3000000000", "--media", "rigid"}, "--sizes 3000000000: block scene: about "},
      {{"--sizes", "1000000000", "--media", "rigid"}, "of host memory on the cpu backend"},
      {{"--max", "9223372036854775807", "--media", "rigid"}, "--max 9223372036854775807: block scene: about "},
      {{"--max", "1000000000000000", "--media", "rigid"}, "--max 1000000000000000: block scene: about "},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"figure", "2", "--backend", "cpu", "--out", work("fig2")};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << c.message << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(work("fig2"))) << "nothing written for " << c.message;
  }
}

// Three short drops: every file is written and every check is computed, and the exit code says
// whether they all passed. 0.3 s is too short for the sphere to settle, so some checks fail.
TEST_F(FigureCommand, Figure3RunsThreeDropsAndWritesItsChecks) {
  // Three runs on 2 busy CPU cores: past run_process's one-minute limit.
  const ProcessResult r =
      start({"figure", "3", "--backend", "cpu", "--resolution", "coarse", "--set", "simulation/duration=0.3",
             "--configs", MSSPH_SOURCE_DIR "/configs", "--out", work("fig3"), "-q"})
          ->wait(std::chrono::minutes(10));
  for (const char* medium : {"rigid", "deformable", "fluid"}) {
    const std::string log = work("fig3/sphere_drop_") + medium + ".h5";
    ASSERT_TRUE(fs::is_regular_file(log)) << r.err;
    EXPECT_EQ(status_of(log), "completed");
  }
  EXPECT_TRUE(fs::is_regular_file(work("fig3/figure3.png")));
  EXPECT_TRUE(fs::is_regular_file(work("fig3/figure3.svg")));
  const nlohmann::json report = read_json(work("fig3/figure3_checks.json"));
  EXPECT_EQ(report["resolution"], "coarse");
  std::size_t failed = 0;
  std::set<std::string> media;
  for (const nlohmann::json& c : report["checks"]) {
    media.insert(c["medium"].get<std::string>());
    failed += c["passed"].get<bool>() ? 0 : 1;
    EXPECT_NE(r.out.find(c["name"].get<std::string>()), std::string::npos) << "printed: " << c["name"];
  }
  EXPECT_EQ(media, (std::set<std::string>{"rigid", "deformable", "fluid"}));
  EXPECT_GT(failed, 0u) << "a sphere cannot have settled after 0.3 s";
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(report["passed"], false);
}

// At 1 cm the deformable block's viscous stress needs the step shrunk with dx^2 (a quarter of
// the scene's 2.5e-4 s); the other drops keep the scene's step.
TEST_F(FigureCommand, Figure3FineShrinksTheDeformableStepWithTheSpacingSquared) {
  const ProcessResult r =
      start({"figure", "3", "--backend", "cpu", "--resolution", "fine", "--set", "simulation/duration=0.0005",
             "--configs", MSSPH_SOURCE_DIR "/configs", "--out", work("fig3"), "-q"})
          ->wait(std::chrono::minutes(10));
  const auto step_of = [&](const std::string& medium) {
    const std::string log = work("fig3/sphere_drop_") + medium + ".h5";
    EXPECT_TRUE(fs::is_regular_file(log)) << r.err;
    const nlohmann::json config = nlohmann::json::parse(h5::read_string_attribute(open_read_only(log).id(), "config"));
    return config["simulation"]["dt"].get<double>();
  };
  EXPECT_DOUBLE_EQ(step_of("deformable"), 6.25e-5);
  EXPECT_DOUBLE_EQ(step_of("rigid"), 2.5e-4);
  EXPECT_DOUBLE_EQ(step_of("fluid"), 2.5e-4);
}

TEST_F(FigureCommand, Figure3RejectsBadArgumentsBeforeRunning) {
  const std::vector<std::vector<std::string>> cases{
      {"--resolution", "medium"},
      {"--configs", work("nowhere")},
      {"--set", "simulation/dt=-1"},
  };
  for (const auto& extra : cases) {
    std::vector<std::string> args{"figure", "3", "--backend", "cpu", "--out", work("fig3")};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << extra[0] << "\n" << r.err;
    EXPECT_NE(r.err.find(extra[0] == "--set" ? "simulation/dt" : extra[0]), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(work("fig3"))) << "nothing written for " << extra[0];
  }
}

// Fg03: every drop's outputs, its log's partial file included, are checked before the first drop
// runs; here the fluid drop's leftover <out>.partial.
TEST_F(FigureCommand, Figure3ChecksEveryDropsOutputsBeforeTheFirst) {
  fs::create_directory(work("fig3"));
  const std::string leftover = work("fig3/sphere_drop_fluid.h5.partial");
  std::ofstream(leftover) << "a killed run's log";
  const ProcessResult r = mssph({"figure", "3", "--backend", "cpu", "--resolution", "coarse", "--set",
                                 "simulation/duration=0.01", "--out", work("fig3"), "-q"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(leftover), std::string::npos) << r.err;
  EXPECT_EQ(work_entries(), (std::vector<std::string>{"fig3", "fig3/sphere_drop_fluid.h5.partial"})) << "no drop ran";
}

TEST_F(FigureCommand, HelpDescribesOutputsAndExitCodes) {
  const ProcessResult two = mssph({"figure", "2", "--help"});
  EXPECT_EQ(two.exit_code, 0);
  for (const char* text : {"--geometry", "--max", "figure2.csv", "figure2_loglog", "median"}) {
    EXPECT_NE(two.out.find(text), std::string::npos) << text;
  }
  const ProcessResult three = mssph({"figure", "3", "--help"});
  EXPECT_EQ(three.exit_code, 0);
  for (const char* text : {"--resolution", "figure3_checks.json", "Exit codes", "coarse"}) {
    EXPECT_NE(three.out.find(text), std::string::npos) << text;
  }
  const ProcessResult tss = mssph({"figure", "tss", "--help"});
  EXPECT_EQ(tss.exit_code, 0);
  EXPECT_NE(tss.out.find("tss_checks.json"), std::string::npos);
  const ProcessResult none = mssph({"figure"});
  EXPECT_EQ(none.exit_code, 2) << "a figure must be named";
}

}  // namespace
}  // namespace mssph::test
