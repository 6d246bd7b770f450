// Bad sweep files and arguments: exit code 2 with the file, JSON path, point and reason, before
// anything runs or is written.
#include "sweep_cli_fixture.hpp"
#include "sweep_test_files.hpp"

#include <gmock/gmock.h>

#include <fstream>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

struct BadSweep {
  std::string name;
  nlohmann::json document;
  std::vector<std::string> expected;  // substrings of stderr
};

class SweepBadInput : public SweepCli {
 protected:
  void expect_rejected(const nlohmann::json& document, const std::vector<std::string>& expected,
                       const std::vector<std::string>& extra_args = {}) {
    expect_file_rejected(write_json(files_, "bad_sweep.json", document), expected, extra_args);
  }
  // A sweep file whose text no JSON value dumps to: deep, overflowing, with a key twice.
  void expect_text_rejected(const std::string& text, const std::vector<std::string>& expected) {
    const std::string file = (files_ / "bad_sweep.json").string();
    std::ofstream(file) << text;
    expect_file_rejected(file, expected, {});
  }
  void expect_file_rejected(const std::string& file, const std::vector<std::string>& expected,
                            const std::vector<std::string>& extra_args) {
    std::vector<std::string> args{"sweep", file, "--out", out(), "--backend", "cpu"};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << "signal " << r.signal << "\n" << r.err;
    for (const std::string& e : expected) EXPECT_THAT(r.err, HasSubstr(e)) << file;
    EXPECT_TRUE(work_entries().empty()) << "nothing may be written before every point is accepted";
  }
  TempDir files_;
};

TEST_F(SweepBadInput, UnknownKeyInTheScene) {
  expect_rejected(
      tiny_sweep({{{"path", "bodies/ball/densty"}, {"values", {400}}}}),
      {"point 0 (densty=400)", "tiny_drop.json: /bodies/ball/densty: unknown key 'densty'", "did you mean 'density'"});
}

TEST_F(SweepBadInput, PathWhoseParentIsNotInTheScene) {
  expect_rejected(tiny_sweep({{{"path", "bodies/bal/density"}, {"values", {400}}}}),
                  {"point 0 (density=400)", "/bodies/bal is not an object in the scene"});
}

TEST_F(SweepBadInput, EmptyValueList) {
  expect_rejected(tiny_sweep({{{"path", "bodies/ball/density"}, {"values", nlohmann::json::array()}}}),
                  {"bad_sweep.json: /parameters/0/values: expected at least one value, got an empty list"});
}

TEST_F(SweepBadInput, AValueTheSceneLoaderRejects) {
  // Only the third point is bad: every point is checked before the first runs.
  expect_rejected(tiny_sweep({{{"path", "materials/contact/viscosity"}, {"values", {1.0, 2.0, -1.0}}}}),
                  {"bad_sweep.json: point 2 (viscosity=-1.0) is rejected by the scene loader",
                   "/materials/contact/viscosity: expected a number >= 0, got -1"});
}

TEST_F(SweepBadInput, UnknownMetric) {
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity}), {{"metrics", {"time_to_peak", "peak_force"}}}),
                  {"bad_sweep.json: /metrics/1: unknown metric \"peak_force\"; known metrics: peak_interaction_force"});
}

// The sweep file through the one strict JSON reader: a value list nested 100000 deep crashed the
// sweep (SIGSEGV), 1e400 and a key twice gave raw library errors (exit 1) or the last value.
TEST_F(SweepBadInput, JsonThatIsDeepOverflowsOrRepeatsAKey) {
  const std::string head = "{\"name\": \"s\", \"scene\": \"" + tiny_scene() + "\", \"parameters\": [";
  expect_text_rejected(head + "{\"path\": \"bodies/ball/density\", \"values\": [" + std::string(100000, '[') +
                           std::string(100000, ']') + "]}]}",
                       {"bad_sweep.json: /parameters/0/values/0/0/0/", "nested more than 64 levels"});
  expect_text_rejected(head + "{\"path\": \"bodies/ball/density\", \"values\": [1e400]}]}",
                       {"bad_sweep.json: /parameters/0/values/0: [json.exception.out_of_range.406]"});
  expect_text_rejected(head + "{\"path\": \"bodies/ball/density\", \"path\": \"x\", \"values\": [1]}]}",
                       {"bad_sweep.json: /parameters/0/path: duplicate key 'path'"});
}

// 2^64 points wrapped the count to 0 ("0 points, every one accepted", exit 0); 1e10 points
// exhausted memory. Both are refused with their true count, the dry run too.
TEST_F(SweepBadInput, MorePointsThanTheLimit) {
  const nlohmann::json range = {{"from", 1.0}, {"to", 2.0}, {"count", 65536}};
  nlohmann::json four = nlohmann::json::array();
  for (const char* path : {"bodies/ball/density", "materials/contact/viscosity", "materials/contact/pressure_stiffness",
                           "simulation/max_speed"}) {
    four.push_back({{"path", path}, {"linear", range}});
  }
  expect_rejected(tiny_sweep(four),
                  {"bad_sweep.json: /parameters: the sweep has 18446744073709551616 points (65536 density x 65536 "
                   "viscosity x 65536 pressure_stiffness x 65536 max_speed); at most 100000 are allowed"},
                  {"--dry-run"});
  const nlohmann::json wide = {{"from", 1.0}, {"to", 2.0}, {"count", 100000}};
  expect_rejected(tiny_sweep({{{"path", "bodies/ball/density"}, {"linear", wide}},
                              {{"path", "materials/contact/viscosity"}, {"linear", wide}}},
                             {{"repetitions", {{"seeds", {1, 2}}}}}),
                  {"the sweep has 20000000000 points (100000 density x 100000 viscosity x 2 seeds)"});
}

// Range values that round to equal ones at 10 digits were reported as a hash collision, exit 1.
TEST_F(SweepBadInput, ARangeWhoseValuesRoundToEqualOnes) {
  expect_rejected(
      tiny_sweep({{{"path", "bodies/ball/density"}, {"linear", {{"from", 400.0}, {"to", 400.0000001}, {"count", 5}}}}}),
      {"bad_sweep.json: /parameters/0/linear/count: 5 values from 400.0 to 400.0000001 round to equal "
       "values at 10 significant digits"});
}

// A sweep named ".." wrote points/ and summary.* into results/ itself.
TEST_F(SweepBadInput, ANameThatIsAFoldersParent) {
  for (const char* name : {"..", "."}) {
    expect_rejected(tiny_sweep(nlohmann::json::array({kDensity}), {{"name", name}}),
                    {"bad_sweep.json: /name: expected a name of letters, digits"});
  }
}

// A damaged DIR/sweep.json gave a Python traceback and exit 1.
TEST_F(SweepBadInput, MergeOfADamagedManifest) {
  std::filesystem::create_directories(out());
  for (const char* text : {"{\"name\": ", "[]", "{\"name\": \"s\"}",
                           R"({"name": "s", "metrics": [], "seeds": [], "parameters": [], "command_line_overrides": [],
                               "points": [7]})"}) {
    std::ofstream(out() + "/sweep.json") << text;
    const ProcessResult r = mssph({"sweep", "merge", out()});
    EXPECT_EQ(r.exit_code, 2) << text << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("sweep.json: damaged: ")) << text;
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("Traceback"))) << text;
  }
}

TEST_F(SweepBadInput, CommandLineSetOfASweptPath) {
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity})), {"--set bodies/ball/density=1", "is swept by"},
                  {"--set", "bodies/ball/density=1"});
}

TEST_F(SweepBadInput, BadArguments) {
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity})), {"--shard 2/2: expected K/N with 0 <= K < N"},
                  {"--shard", "2/2"});
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity})), {"--gpus and --jobs"},
                  {"--gpus", "0,1", "--jobs", "2"});
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity})), {"--gpus 0,,1"}, {"--gpus", "0,,1"});
  expect_rejected(tiny_sweep(nlohmann::json::array({kDensity})), {"only shape the scripts of --emit-slurm"},
                  {"--partition", "gpu"});
}

TEST_F(SweepBadInput, RunRejectsATagWithoutANameBeforeWriting) {
  for (const char* tag : {"a/b=1", "=1", "no_equals"}) {
    const ProcessResult r = mssph({"run", data_file("tiny_drop.json"), "--out", work("tagged.h5"), "--tag", tag});
    EXPECT_EQ(r.exit_code, 2) << tag << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr(std::string("--tag ") + tag + ": expected NAME=VALUE"));
    EXPECT_TRUE(work_entries().empty()) << tag;
  }
}

TEST_F(SweepBadInput, MergeAndPlotOfAFolderThatIsNoSweep) {
  for (const char* sub : {"merge", "plot"}) {
    const ProcessResult r = mssph({"sweep", sub, work("nothing_here")});
    EXPECT_EQ(r.exit_code, 2) << sub << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("not the --out folder of a sweep")) << sub;
  }
}

}  // namespace
}  // namespace mssph::test
