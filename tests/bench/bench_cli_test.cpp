// `mssph bench compare` through the real binary: exit codes 0, 1 and 2, the machine check and
// --force, the three formats; `mssph bench` bad input and help.
#include "cli_fixture.hpp"

#include <fstream>

namespace mssph::test {
namespace {

void expect_mentions(const std::string& text, const std::vector<std::string>& phrases) {
  for (const std::string& p : phrases) EXPECT_NE(text.find(p), std::string::npos) << "\"" << p << "\" in\n" << text;
}

// A Google Benchmark file as `mssph bench --out` writes one: per benchmark, one "iteration"
// entry per repetition and the aggregates after them (which compare must ignore).
nlohmann::json benchmark_file(const std::map<std::string, std::vector<double>>& microseconds,
                              const std::string& cpu = "Test CPU (2 threads)") {
  nlohmann::json doc = {{"context",
                         {{"num_cpus", 2},
                          {"mssph_cpu", cpu},
                          {"mssph_gpu", "none (built without CUDA)"},
                          {"mssph_build_type", "Release"}}},
                        {"benchmarks", nlohmann::json::array()}};
  for (const auto& [name, times] : microseconds) {
    for (std::size_t i = 0; i < times.size(); ++i) {
      doc["benchmarks"].push_back({{"name", name},
                                   {"run_name", name},
                                   {"run_type", "iteration"},
                                   {"repetition_index", i},
                                   {"real_time", times[i]},
                                   {"time_unit", "us"}});
    }
    doc["benchmarks"].push_back({{"name", name + "_median"},
                                 {"run_name", name},
                                 {"run_type", "aggregate"},
                                 {"aggregate_name", "median"},
                                 {"real_time", 1e9},
                                 {"time_unit", "us"}});
  }
  return doc;
}

const std::vector<double> kBase{100, 102, 98, 101, 99, 103};

class BenchCompare : public Cli {
 protected:
  std::string file(const std::string& name, const nlohmann::json& doc) const {
    std::ofstream(work(name)) << doc.dump(1);
    return work(name);
  }
};

TEST_F(BenchCompare, SameTimesPassWithExitZero) {
  const std::string a = file("a.json", benchmark_file({{"step/cpu/fluid/2000/manual_time", kBase}}));
  const std::string b =
      file("b.json", benchmark_file({{"step/cpu/fluid/2000/manual_time", {101, 99, 100, 102, 98, 100.5}}}));
  const ProcessResult r = mssph({"bench", "compare", a, b});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  expect_mentions(r.out, {"step/cpu/fluid/2000/manual_time", "unchanged", "Mann-Whitney", "Result: pass"});
}

TEST_F(BenchCompare, SignificantTwofoldSlowdownFailsWithExitOne) {
  std::vector<double> slow;
  for (double t : kBase) slow.push_back(2.0 * t);
  const std::string a = file("a.json", benchmark_file({{"x", kBase}, {"y", kBase}}));
  const std::string b = file("b.json", benchmark_file({{"x", slow}, {"y", kBase}}));
  const ProcessResult r = mssph({"bench", "compare", a, b, "--format", "json"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["failed"].get<bool>());
  EXPECT_EQ(report["benchmarks"][0]["verdict"], "SLOWER");
  EXPECT_NEAR(report["benchmarks"][0]["ratio"].get<double>(), 2.0, 1e-9);
  EXPECT_EQ(report["benchmarks"][1]["verdict"], "unchanged");
  // The same slowdown within a threshold of 150 % passes.
  EXPECT_EQ(mssph({"bench", "compare", a, b, "--threshold", "150%"}).exit_code, 0);
}

TEST_F(BenchCompare, MarkdownIsATableForAJobSummary) {
  const std::string a = file("a.json", benchmark_file({{"x", kBase}}));
  const ProcessResult r = mssph({"bench", "compare", a, a, "--format", "markdown"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  expect_mentions(r.out, {"| benchmark | baseline | current | ratio | p | n | verdict |", "| --- |", "| `x` |"});
}

TEST_F(BenchCompare, DifferentMachinesAreRefusedUnlessForced) {
  const std::string a = file("a.json", benchmark_file({{"x", kBase}}, "Intel Xeon (2 threads)"));
  const std::string b = file("b.json", benchmark_file({{"x", kBase}}, "AMD EPYC (2 threads)"));
  const ProcessResult refused = mssph({"bench", "compare", a, b});
  EXPECT_EQ(refused.exit_code, 2);
  expect_mentions(refused.err, {"mssph_cpu", "Intel Xeon (2 threads)", "AMD EPYC (2 threads)", "--force"});
  const ProcessResult forced = mssph({"bench", "compare", a, b, "--force"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  expect_mentions(forced.out, {"forced: mssph_cpu differs"});
}

TEST_F(BenchCompare, BadInputExitsTwoAndSaysWhy) {
  const std::string a = file("a.json", benchmark_file({{"x", kBase}}));
  const std::string other = file("other.json", benchmark_file({{"y", kBase}}));
  const std::string scene = data_file("tiny_drop.json");  // JSON, but not benchmark output
  std::ofstream(work("broken.json")) << "{\"context\": {";
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"bench", "compare", a, work("missing.json")}, "missing.json: cannot open"},
      {{"bench", "compare", a, scene}, "tiny_drop.json: no \"context\" object"},
      {{"bench", "compare", work("broken.json"), a}, "broken.json: not JSON"},
      {{"bench", "compare", a, other}, "no benchmark in common"},
      {{"bench", "compare", a, a, "--threshold", "fast"}, "--threshold fast"},
      {{"bench", "compare", a}, "current"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = mssph(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args.back() << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.message << " in\n" << r.err;
  }
}

// Files no Google Benchmark run writes: exit 2 naming the file and the JSON path, never a raw
// library exception (exit 1) or a crash; a threshold that can never fail is refused too.
TEST_F(BenchCompare, HostileFilesAndThresholdsExitTwoNamingTheValue) {
  const std::string a = file("a.json", benchmark_file({{"x", kBase}}));
  const std::string text = benchmark_file({{"x", kBase}}).dump();
  const auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    std::ofstream(work(name)) << changed;
    return work(name);
  };
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases{
      // A context value 100000 arrays deep was serialised whole for its text: SIGSEGV.
      {{"bench", "compare", a,
        variant("deep.json", "\"Release\"", std::string(100000, '[') + std::string(100000, ']'))},
       "deep.json: /context/mssph_build_type/0/0/"},
      {{"bench", "compare", a, variant("overflow.json", "\"real_time\":100.0", "\"real_time\":1e400")},
       "overflow.json: /benchmarks/0/real_time: [json.exception.out_of_range.406] number overflow"},
      {{"bench", "compare", a, variant("run_type.json", "\"run_type\":\"iteration\"", "\"run_type\":5")},
       "run_type.json: /benchmarks/0/run_type: expected a string, got number 5"},
      {{"bench", "compare", a, variant("twice.json", "\"real_time\":100.0", "\"real_time\":100.0,\"real_time\":1.0")},
       "twice.json: /benchmarks/0/real_time: duplicate key 'real_time'"},
      {{"bench", "compare", a, a, "--threshold", "inf"}, "--threshold inf: expected a positive fraction"},
      {{"bench", "compare", a, a, "--threshold", "nan%"}, "--threshold nan%: expected a positive fraction"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = mssph(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.message << "\nsignal " << r.signal << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.message << " in\n" << r.err;
  }
}

// The CI gate's normalization through the binary: a machine that takes 1.5 times as long for the
// current file (its calibration and the benchmark alike) passes normalized and fails raw; a file without the
// calibration benchmark is bad input, named.
TEST_F(BenchCompare, NormalizedByTheCalibrationAMachineSlowdownPasses) {
  std::vector<double> slow;
  for (double t : kBase) slow.push_back(1.5 * t);
  const std::string a = file("a.json", benchmark_file({{"calibration/cpu", kBase}, {"x", kBase}}));
  const std::string b = file("b.json", benchmark_file({{"calibration/cpu", slow}, {"x", slow}}));
  EXPECT_EQ(mssph({"bench", "compare", a, b}).exit_code, 1);
  const ProcessResult r = mssph({"bench", "compare", a, b, "--normalize-by", "calibration/cpu"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  expect_mentions(r.out, {"Normalized by calibration/cpu", "1.500x", "unchanged", "Result: pass"});
  const std::string c = file("c.json", benchmark_file({{"x", slow}}));
  const ProcessResult missing = mssph({"bench", "compare", a, c, "--normalize-by", "calibration/cpu"});
  EXPECT_EQ(missing.exit_code, 2);
  expect_mentions(missing.err, {"c.json", "no benchmark \"calibration/cpu\" to normalize by"});
}

TEST_F(BenchCompare, TooFewRepetitionsAreExplained) {
  const std::string a = file("a.json", benchmark_file({{"x", {100, 101, 99}}}));
  const std::string b = file("b.json", benchmark_file({{"x", {300, 301, 299}}}));
  const ProcessResult r = mssph({"bench", "compare", a, b});
  EXPECT_EQ(r.exit_code, 0) << r.out;  // three times as long, yet 3 repetitions cannot show it
  expect_mentions(r.out, {"too few repetitions", "smallest p-value the test can give is 0.1"});
}

using Bench = Cli;

TEST_F(Bench, HelpDocumentsNamesContextTestHookAndExitCodes) {
  const ProcessResult r = mssph({"bench", "--help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  expect_mentions(r.out,
                  {"--backend", "--filter", "--repetitions", "--min-time", "--out", "--list",
                   "step/<backend>/<medium>/<particles>", "haptic_tick/<backend>", "mssph_cpu", "mssph_gpu_driver",
                   "mssph_git_commit", "MSSPH_BENCH_STEP_DELAY_US", "Test hook", "Exit codes"});
  const ProcessResult c = mssph({"bench", "compare", "--help"});
  EXPECT_EQ(c.exit_code, 0) << c.err;
  expect_mentions(c.out, {"--threshold", "--format", "--force", "--normalize-by", "--alpha", "Mann-Whitney U", "exact",
                          "normal approximation", "0.05", "Exit codes: 0", "1 at least one", "2 bad"});
  expect_mentions(mssph({"--help"}).out, {"bench"});
}

TEST_F(Bench, ListsTheStableNames) {
  const ProcessResult r = mssph({"bench", "--backend", "cpu", "--list"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const std::string medium : {"fluid", "rigid", "deformable", "mixed"}) {
    expect_mentions(r.out, {"step/cpu/" + medium + "/2000/manual_time", "step/cpu/" + medium + "/30000/manual_time"});
  }
  expect_mentions(r.out, {"haptic_tick/cpu", "calibration/cpu"});
}

TEST_F(Bench, BadInputExitsTwo) {
  const ProcessResult nothing = mssph({"bench", "--backend", "cpu", "--filter", "no_such_benchmark"});
  EXPECT_EQ(nothing.exit_code, 2);
  expect_mentions(nothing.err, {"no benchmark matches --filter \"no_such_benchmark\""});
  const ProcessResult hook =
      run_process({"/usr/bin/env", "MSSPH_BENCH_STEP_DELAY_US=soon", MSSPH_BINARY, "bench", "--list"}, work_.path());
  EXPECT_EQ(hook.exit_code, 2);
  expect_mentions(hook.err, {"MSSPH_BENCH_STEP_DELAY_US=soon", "microseconds"});
  EXPECT_EQ(mssph({"bench", work("no_scene.json")}).exit_code, 2);
  const ProcessResult set = mssph({"bench", "--set", "simulation/dt=1e-4"});
  EXPECT_EQ(set.exit_code, 2);
  expect_mentions(set.err, {"--set applies to a scene file"});
  EXPECT_EQ(mssph({"bench", "--backend", "gpu"}).exit_code, 2);
}

}  // namespace
}  // namespace mssph::test
