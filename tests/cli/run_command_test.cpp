// `mssph run` on a tiny scene: what a successful run prints and writes.
#include "cli_fixture.hpp"
#include "python_tools.hpp"

#include <algorithm>
#include <cmath>

namespace mssph::test {
namespace {

std::size_t steps_of(const nlohmann::json& scene) {
  return static_cast<std::size_t>(
      std::llround(scene["simulation"]["duration"].get<double>() / scene["simulation"]["dt"].get<double>()));
}

using RunCommand = Cli;

TEST_F(RunCommand, CompletesAndNamesTheLogOnStdout) {
  const std::string out = work("run.h5");
  const ProcessResult r = mssph({"run", kTinyDrop, "--backend", "reference", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one summary line:\n" << r.out;
  EXPECT_EQ(r.out.rfind(out + ": ", 0), 0u) << r.out;
  EXPECT_NE(r.err.find("tiny_drop"), std::string::npos) << "start-up line expected without -q:\n" << r.err;

  const nlohmann::json scene = read_json(kTinyDrop);
  const h5::Handle file = open_read_only(out);
  EXPECT_EQ(h5::read_string_attribute(file.id(), "status"), "completed");
  EXPECT_EQ(h5::read_string_attribute(file.id(), "backend"), "reference");
  EXPECT_EQ(h5::read_string_attribute(file.id(), "config_path"), kTinyDrop);
  EXPECT_EQ(h5::read_string_attribute(file.id(), "config_file"), read_file(kTinyDrop));
  EXPECT_EQ(nlohmann::json::parse(h5::read_string_attribute(file.id(), "config")), scene);
  EXPECT_EQ(read_integer_attribute(file.id(), "seed"), scene["simulation"]["seed"].get<long long>());
  EXPECT_EQ(read_integer_attribute(file.id(), "steps"), static_cast<long long>(steps_of(scene)));
  const std::vector<double> time = read_doubles(file.id(), "/time");
  ASSERT_FALSE(time.empty());
  // The last sample is taken at the last step: the end of the run within rounding of the sum
  // of steps, far below a step.
  const double dt = scene["simulation"]["dt"].get<double>();
  EXPECT_NEAR(time.back(), scene["simulation"]["duration"].get<double>(), 1e-6 * dt);
}

TEST_F(RunCommand, QuietPrintsOnlyTheSummary) {
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", work("quiet.h5"), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "-q leaves stderr to warnings and errors; this scene has none";
  EXPECT_EQ(r.out.rfind(work("quiet.h5") + ": ", 0), 0u) << r.out;
}

TEST_F(RunCommand, WritesToTheDocumentedDefaultPath) {
  const ProcessResult r = mssph({"run", kTinyDrop, "--backend", "reference", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string expected = "results/runs/tiny_drop_reference.h5";  // `mssph run --help`
  EXPECT_EQ(r.out.rfind(expected + ": ", 0), 0u) << r.out;
  EXPECT_EQ(work_entries(), (std::vector<std::string>{"results", "results/runs", expected}));
  EXPECT_EQ(status_of(work(expected)), "completed");
}

TEST_F(RunCommand, SetOverridesReachTheLoggedConfig) {
  const std::string out = work("overridden.h5");
  // --set before the scene: each --set takes exactly one PATH=VALUE.
  const ProcessResult r = mssph(
      {"run", "--set", "simulation/duration=0.01", "--set", "/simulation/seed=99", kTinyDrop, "--out", out, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json expected = read_json(kTinyDrop);
  expected["simulation"]["duration"] = 0.01;
  expected["simulation"]["seed"] = 99;
  const h5::Handle file = open_read_only(out);
  EXPECT_EQ(nlohmann::json::parse(h5::read_string_attribute(file.id(), "config")), expected);
  EXPECT_EQ(h5::read_string_attribute(file.id(), "config_file"), read_file(kTinyDrop)) << "the file as written";
  EXPECT_EQ(read_integer_attribute(file.id(), "seed"), 99);
  EXPECT_EQ(read_integer_attribute(file.id(), "steps"), static_cast<long long>(steps_of(expected)));
  const std::string command_line = h5::read_string_attribute(file.id(), "command_line");
  EXPECT_NE(command_line.find("--set simulation/duration=0.01"), std::string::npos) << command_line;
}

TEST_F(RunCommand, SnapshotsComeWithAValidXdmfSidecar) {
  const std::string out = work("snapshots.h5");
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", out, "--set", "output/snapshot_interval=0.01", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ProcessResult check = check_xdmf(out + ".xdmf");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  // One snapshot at the start and one per interval: 0, 0.01 and 0.02 s.
  const nlohmann::json scene = read_json(kTinyDrop);
  const long long expected = 1 + std::llround(scene["simulation"]["duration"].get<double>() / 0.01);
  EXPECT_NE(check.out.find("grids " + std::to_string(expected)), std::string::npos) << check.out;
  EXPECT_NE(read_file(out + ".xdmf").find("/particles/body"), std::string::npos) << "body index per particle";
  EXPECT_FALSE(std::filesystem::exists(out + ".partial.xdmf")) << "the running log's sidecar is gone";
}

// The README promises units and a description on every dataset: checked on a log with body
// series, haptics, timing, the body index, snapshots and checkpoints (one after every step), as
// h5py reads it.
TEST_F(RunCommand, EveryDatasetHasUnitsAndADescription) {
  const std::string out = work("described.h5");
  ASSERT_EQ(mssph({"run", kTinyDrop, "--out", out, "--set", "output/snapshot_interval=0.01", "--phase-timing",
                   "--checkpoint-interval", "1e-9", "-q"})
                .exit_code,
            0);
  std::size_t datasets = 0;
  const nlohmann::json summary = h5py_summary(out);
  EXPECT_TRUE(summary["objects"].contains("/timing/phases")) << "--phase-timing logs the phases";
  EXPECT_TRUE(summary["objects"].contains("/checkpoint/a/state/backend/position")) << "checkpoints were written";
  for (const auto& [path, object] : summary["objects"].items()) {
    if (object["kind"] != "dataset") continue;
    ++datasets;
    EXPECT_TRUE(object["attributes"].contains("units")) << path;
    EXPECT_FALSE(object["attributes"].value("description", "").empty()) << path;
  }
  EXPECT_GT(datasets, 30u) << "body, haptics, timing and snapshot datasets";
}

// Phase times only when asked for (a GPU times them with events that lengthen its steps), with
// the phase names every backend shares and one row per step.
TEST_F(RunCommand, PhaseTimesAreLoggedOnlyWithPhaseTiming) {
  const std::string plain = work("plain.h5");
  const std::string timed = work("timed.h5");
  ASSERT_EQ(mssph({"run", kTinyDrop, "--backend", "cpu", "--out", plain, "-q"}).exit_code, 0);
  ASSERT_EQ(mssph({"run", kTinyDrop, "--backend", "cpu", "--out", timed, "-q", "--phase-timing"}).exit_code, 0);
  EXPECT_FALSE(h5py_summary(plain)["objects"].contains("/timing/phases"));
  const nlohmann::json objects = h5py_summary(timed)["objects"];
  ASSERT_TRUE(objects.contains("/timing/phases"));
  EXPECT_EQ(objects["/timing"]["attributes"]["phase_names"],
            (nlohmann::json{"neighbours", "rotations", "densities", "forces", "integration"}));
  const h5::Handle file = open_read_only(timed);
  const std::vector<double> phases = read_doubles(file.id(), "/timing/phases");
  EXPECT_EQ(phases.size(), 5 * steps_of(read_json(kTinyDrop)));
  EXPECT_TRUE(std::all_of(phases.begin(), phases.end(), [](double s) { return std::isfinite(s) && s >= 0.0; }));
}

// The cpu backend keeps neighbour lists with a skin and builds its grid only when they expire:
// the log gives the builds per step, a whole number of builds (the first step's among them) over
// the run's steps. The reference backend builds every step and logs no rate.
TEST_F(RunCommand, LogsTheGridBuildRateOfBackendsWithLists) {
  const std::string listed = work("listed.h5");
  const std::string reference = work("reference.h5");
  ASSERT_EQ(mssph({"run", kTinyDrop, "--backend", "cpu", "--out", listed, "-q"}).exit_code, 0);
  ASSERT_EQ(mssph({"run", kTinyDrop, "--backend", "reference", "--out", reference, "-q"}).exit_code, 0);
  const double steps = static_cast<double>(steps_of(read_json(kTinyDrop)));
  const double rate = h5::read_double_attribute(open_read_only(listed).id(), "neighbour_grid_builds_per_step");
  const double builds = rate * steps;
  EXPECT_GE(builds, 1.0 - 1e-9) << "the first step builds the grid";
  EXPECT_LT(builds, steps) << "lists with a skin outlast some steps";
  EXPECT_NEAR(builds, std::round(builds), 1e-9) << "a count of builds over the steps";
  EXPECT_FALSE(has_attribute(open_read_only(reference).id(), "neighbour_grid_builds_per_step"));
}

}  // namespace
}  // namespace mssph::test
