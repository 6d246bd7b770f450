// `mssph sweep` end to end: every point an ordinary `mssph run` with its own log, named by its
// hash and tagged with its parameters; the summary, the dry run, the Slurm scripts and the plots.
#include "cli/commands.hpp"
#include "sweep/sweep_points.hpp"
#include "sweep_cli_fixture.hpp"

#include <gmock/gmock.h>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

using SweepRun = SweepCli;

TEST_F(SweepRun, RunsEveryPointAsAnOrdinaryRunAndSummarises) {
  const ProcessResult r = mssph({"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cpu", "--jobs", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("4 to run, 2 at a time"));
  EXPECT_THAT(r.err, HasSubstr("[4/4 done, 0 running, 0 failed"));
  const nlohmann::json m = manifest();
  ASSERT_EQ(m["points"].size(), 4u);
  for (const nlohmann::json& point : m["points"]) {
    const std::string log = log_of(point);
    const h5::Handle file = open_read_only(log);
    EXPECT_EQ(h5::read_string_attribute(file.id(), "status"), "completed") << log;
    // The name is the hash of the scene the log says it ran.
    const std::string config = h5::read_string_attribute(file.id(), "config");
    EXPECT_EQ(sweep::point_hash(nlohmann::json::parse(config)), point["hash"].get<std::string>());
    EXPECT_EQ(std::filesystem::path(log).filename().string(), "point-" + point["hash"].get<std::string>() + ".h5");
    // Its parameters are attributes of /tags.
    const h5::Handle tags = open_object(file.id(), "/tags");
    EXPECT_EQ(h5::read_double_attribute(tags.id(), "k"), point["parameters"]["k"].get<double>());
    EXPECT_EQ(read_integer_attribute(tags.id(), "density"), point["parameters"]["density"].get<long long>());
    EXPECT_EQ(h5::read_string_attribute(tags.id(), "point"), point["hash"].get<std::string>());
  }
  EXPECT_EQ(csv_column("state"), std::vector<std::string>(4, "completed"));
  EXPECT_EQ(csv_column("k"), (std::vector<std::string>{"100.0", "100.0", "1000.0", "1000.0"}));
  EXPECT_EQ(csv_column("density"), (std::vector<std::string>{"400", "600", "400", "600"}));
  for (const std::string& force : csv_column("peak_interaction_force")) {
    EXPECT_GT(std::stod(force), 0.0) << "the ball reaches the ground within 0.1 s";
  }

  // summary.h5 reaches every log through its external link, from any working directory.
  const h5::Handle summary = open_read_only(out() + "/summary.h5");
  for (const nlohmann::json& point : m["points"]) {
    const h5::Handle linked = open_object(summary.id(), "/points/point-" + point["hash"].get<std::string>() + "/log");
    EXPECT_EQ(h5::read_string_attribute(linked.id(), "status"), "completed");
  }
}

TEST_F(SweepRun, APointsLogIsTheLogOfTheSameMssphRun) {
  ASSERT_EQ(mssph({"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cpu"}).exit_code, 0);
  const nlohmann::json point = manifest()["points"][3];
  std::vector<std::string> args{"run",   data_file("tiny_drop.json"), "--backend", "cpu",
                                "--out", work("direct.h5"),           "-q"};
  for (const auto& o : point["overrides"]) {
    args.push_back("--set");
    args.push_back(o.get<std::string>());
  }
  ASSERT_EQ(mssph(args).exit_code, 0);
  const h5::Handle direct = open_read_only(work("direct.h5"));
  const h5::Handle swept = open_read_only(log_of(point));
  for (const char* series :
       {"/time", "/bodies/ball/centre_of_mass", "/bodies/ball/interaction_force", "/haptics/rendered/force"}) {
    EXPECT_EQ(read_doubles(swept.id(), series), read_doubles(direct.id(), series)) << series;
  }
}

TEST_F(SweepRun, DryRunValidatesAndListsWithoutWriting) {
  const ProcessResult r = mssph({"sweep", tiny_product_sweep(), "--out", out(), "--dry-run"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("4 points"));
  EXPECT_THAT(r.out, HasSubstr("missing  k=1000.0 density=600"));
  EXPECT_TRUE(work_entries().empty());
}

TEST_F(SweepRun, EmitSlurmWritesTheScriptsAndRunsNothing) {
  const ProcessResult r = mssph({"sweep", tiny_product_sweep(), "--out", out(), "--emit-slurm", "--shards", "3",
                                 "--partition", "debug", "--set", "simulation/particle_spacing=0.05"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("bash " + out() + "/slurm/submit.sh"));
  const std::string array = read_file(out() + "/slurm/sweep_array.sbatch");
  EXPECT_THAT(array, HasSubstr("#SBATCH --array=0-2\n"));
  EXPECT_THAT(array, HasSubstr("#SBATCH --partition=debug\n"));
  EXPECT_THAT(array, HasSubstr("--shard \"${SLURM_ARRAY_TASK_ID}/3\" --set 'simulation/particle_spacing=0.05'"));
  EXPECT_EQ(manifest()["points"].size(), 4u);
  EXPECT_FALSE(std::filesystem::exists(out() + "/points")) << "nothing ran";
}

TEST_F(SweepRun, PlotDrawsEveryNumericMetricAsLinesAndHeatMaps) {
  ASSERT_EQ(mssph({"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cpu"}).exit_code, 0);
  const ProcessResult r = mssph({"sweep", "plot", out(), "--metric", "peak_interaction_force"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"peak_interaction_force.png", "peak_interaction_force.svg",
                           "peak_interaction_force_heatmap.png", "peak_interaction_force_heatmap.svg"}) {
    EXPECT_GT(std::filesystem::file_size(out() + "/plots/" + file), 1000u) << file;
  }
  EXPECT_THAT(read_file(out() + "/plots/peak_interaction_force.svg"), HasSubstr("density = 600"))
      << "one line per value of the second parameter";
  const ProcessResult bad = mssph({"sweep", "plot", out(), "--metric", "final_status"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("numeric metrics are peak_interaction_force, time_to_peak, peak_rendered_force"));
}

TEST_F(SweepRun, HelpListsEveryOptionResumeAndExitCodes) {
  const ProcessResult r = mssph({"sweep", "--help"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  CLI::App app;
  int exit_code = 0;
  cli::add_sweep_command(app, exit_code);
  for (const CLI::Option* option : app.get_subcommand("sweep")->get_options())
    EXPECT_THAT(r.out, HasSubstr(option->get_name()));
  for (const char* phrase : {"merge", "plot", "--retry-failed", "\"completed\"", "point-<hash>.h5",
                             "SLURM_ARRAY_TASK_ID", "Exit codes: 0", "2 bad input", "3 a point failed"}) {
    EXPECT_THAT(r.out, HasSubstr(phrase));
  }
}

}  // namespace
}  // namespace mssph::test
