// `mssph validate`: the table, report.json, validation.h5 and report.md on a tiny case; a wrong
// expectation FAILs with exit code 1; a backend that cannot run here is SKIPPED with its reason;
// bad arguments exit 2 and write nothing.
#include "cli_fixture.hpp"
#include "framework/backends.hpp"
#include "framework/validation_case.hpp"
#include "physics/cantilever_frequency/cantilever_frequency.hpp"

#include <gmock/gmock.h>

#include <fstream>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

class Validate : public Cli {};

TEST_F(Validate, TinyCaseWritesTheTableAndEveryReportFile) {
  const ProcessResult r = mssph({"validate", "--quick", "--case", "coupling_step", "--out", "report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("suite"));
  EXPECT_THAT(r.out, HasSubstr("tolerance"));
  EXPECT_THAT(r.out, HasSubstr("coupling_step"));
  EXPECT_THAT(r.out, HasSubstr("overshoot"));
  EXPECT_THAT(r.out, HasSubstr("PASS"));
  EXPECT_THAT(r.out, HasSubstr("cases: 1 passed, 0 failed, 0 skipped"));

  const nlohmann::json report = read_json(work("report/report.json"));
  EXPECT_EQ(report["run"]["mode"], "quick");
  // The recorded command repeats the run: it names the fresh seed the run drew.
  EXPECT_THAT(report["run"]["command_line"].get<std::string>(),
              HasSubstr("--case coupling_step --seed " + std::to_string(report["run"]["seed"].get<std::uint64_t>())));
  for (const char* key : {"git_commit", "date", "physics_backend", "physics_device", "physics_precision", "host_cpu"}) {
    EXPECT_FALSE(report["run"][key].get<std::string>().empty()) << key;
  }
  ASSERT_EQ(report["cases"].size(), 1u);
  EXPECT_EQ(report["cases"][0]["case"], "coupling_step");
  EXPECT_EQ(report["cases"][0]["status"], "PASS");
  EXPECT_EQ(report["cases"][0]["checks"].size(), 4u);
  for (const auto& check : report["cases"][0]["checks"]) {
    EXPECT_TRUE(check["measured"].is_number());
    EXPECT_EQ(check["status"], "PASS");
  }

  const h5::Handle h5 = open_read_only(work("report/validation.h5"));
  EXPECT_EQ(h5::read_string_attribute(h5.id(), "git_commit"), report["run"]["git_commit"].get<std::string>());
  EXPECT_EQ(read_doubles(h5.id(), "/physics/coupling_step/translation_step/x").size(),
            read_doubles(h5.id(), "/physics/coupling_step/translation_step/y0").size());
  EXPECT_GT(read_doubles(h5.id(), "/physics/coupling_step/translation_step/x").size(), 1000u);

  const std::string markdown = read_file(work("report/report.md"));
  EXPECT_THAT(markdown, HasSubstr("coupling_step"));
  EXPECT_THAT(markdown, HasSubstr(report["run"]["git_commit"].get<std::string>()));
  EXPECT_THAT(markdown, HasSubstr("physics_coupling_step_translation_step.png"));
  EXPECT_TRUE(std::filesystem::exists(work("report/physics_coupling_step_translation_step.png")));
}

TEST_F(Validate, WrongExpectationFailsWithExitCode1) {
  const ProcessResult r = mssph({"validate", "--case", "wrong_expectation", "--out", "report"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.out, HasSubstr("FAIL"));
  EXPECT_THAT(r.out, HasSubstr("cases: 0 passed, 1 failed, 0 skipped"));
  EXPECT_EQ(read_json(work("report/report.json"))["cases"][0]["status"], "FAIL");
}

TEST_F(Validate, CudaWithoutAGpuIsSkippedWithTheReason) {
  const std::string why = why_backend_cannot_run("cuda");
  if (why.empty()) GTEST_SKIP() << "this machine runs cuda: nothing is skipped";
  const ProcessResult r =
      mssph({"validate", "--backend", "cuda", "--case", "one_step", "--case", "hydrostatic", "--out", "report"});
  EXPECT_EQ(r.exit_code, 0) << r.err;  // skipped is not failed
  EXPECT_THAT(r.out, HasSubstr("SKIPPED (" + why + ")"));
  EXPECT_THAT(r.out, ::testing::Not(HasSubstr("PASS")));
  EXPECT_THAT(r.out, HasSubstr("cases: 0 passed, 0 failed, 2 skipped"));
  // The report is held in a variable: a range-for over read_json(...)["cases"] would iterate an
  // element of a temporary destroyed before the loop body runs (C++20 extends only the outer
  // temporary's lifetime).
  const nlohmann::json report = read_json(work("report/report.json"));
  for (const auto& c : report["cases"]) EXPECT_EQ(c["status"], "SKIPPED");
}

TEST_F(Validate, BadArgumentsExit2AndWriteNothing) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"validate", "--suite", "everything"},
                                               std::vector<std::string>{"validate", "--backend", "gpu"},
                                               std::vector<std::string>{"validate", "--case", "no_such_case"},
                                               std::vector<std::string>{"validate", "--quick", "extra"}}) {
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << args.back() << "\n" << r.err;
    EXPECT_EQ(work_entries(), std::vector<std::string>{}) << args.back();
  }
  const ProcessResult r = mssph({"validate", "--case", "no_such_case"});
  EXPECT_THAT(r.err, HasSubstr("--case no_such_case: no such case"));
  EXPECT_THAT(r.err, HasSubstr("hydrostatic"));  // the known cases are listed
}

// V08: the report's files are replaced only with --force, like every output of mssph; refused,
// nothing is run and nothing in the folder changes.
TEST_F(Validate, AnEarlierReportIsReplacedOnlyWithForce) {
  std::filesystem::create_directory(work("report"));
  for (const char* name : {"report.json", "report.md"}) std::ofstream(work("report/") + name) << "precious";
  const std::vector<std::string> args{"validate", "--case", "wrong_expectation", "--out", work("report")};
  for (const char* name : {"report.json", "report.md"}) {
    SCOPED_TRACE(name);
    expect_refused_and_untouched(args, work("report/") + name, "exists; pass --force");
  }
  EXPECT_EQ(work_entries(), (std::vector<std::string>{"report", "report/report.json", "report/report.md"}));
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  const ProcessResult r = mssph(forced);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // the case fails on purpose
  EXPECT_EQ(read_json(work("report/report.json"))["cases"][0]["status"], "FAIL");
  EXPECT_THAT(read_file(work("report/report.md")), HasSubstr("wrong_expectation"));
}

// The Timoshenko correction the cantilever frequency case quotes is what its script computes.
TEST_F(Validate, TimoshenkoRatioOfTheFrequencyCaseIsTheScripts) {
  const ProcessResult r = run_process(
      {MSSPH_PYTHON, std::string(MSSPH_SOURCE_DIR) + "/scripts/validation/timoshenko_cantilever.py"}, work("."));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t at = r.out.find("ratio = ");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(r.out.substr(at + 8)), validation::kTimoshenkoF1Ratio, 1e-5) << r.out;
}

// The suites, case by case: each required check has a registered case whose folder holds
// the README with its formula, source and tolerance (validation/README.md maps checks to cases).
TEST(ValidateCases, EveryRequiredCaseIsRegisteredWithItsReadme) {
  const std::vector<std::pair<std::string, std::string>> required{{"kernels", "one_step"},
                                                                  {"kernels", "sphere_drops"},
                                                                  {"kernels", "haptic_scenes"},
                                                                  {"physics", "hydrostatic"},
                                                                  {"physics", "archimedes"},
                                                                  {"physics", "torque_free_spin"},
                                                                  {"physics", "rotation_invariance"},
                                                                  {"physics", "patch_tests"},
                                                                  {"physics", "bar_vibration"},
                                                                  {"physics", "cantilever"},
                                                                  {"physics", "cantilever_frequency"},
                                                                  {"physics", "hertz"},
                                                                  {"physics", "coupling_step"},
                                                                  {"physics", "passivity"},
                                                                  {"convergence", "hydrostatic_slope"},
                                                                  {"convergence", "floating_depth"},
                                                                  {"convergence", "cantilever_deflection"}};
  const auto& cases = validation::all_cases();
  for (const auto& [suite, case_name] : required) {
    const std::string& name = case_name;  // named again: Clang before 16 cannot capture a structured binding
    const auto found = std::find_if(cases.begin(), cases.end(), [&](const auto& c) { return c.name == name; });
    ASSERT_NE(found, cases.end()) << name;
    EXPECT_EQ(found->suite, suite) << name;
    EXPECT_TRUE(std::filesystem::exists(validation::validation_file(found->folder + "/README.md"))) << name;
  }
}

}  // namespace
}  // namespace mssph::test
