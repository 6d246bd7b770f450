// Verdicts, the machine check and reading Google Benchmark JSON.
#include "bench/bench_comparison.hpp"
#include "bench/comparison_format.hpp"
#include "temp_dir.hpp"
#include "util/errors.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace mssph::bench {
namespace {

// Benchmarks in the order given, as in a file.
BenchmarkResults results(const std::string& path, const std::vector<std::pair<std::string, std::vector<double>>>& times,
                         const std::string& cpu = "Test CPU (2 threads)") {
  BenchmarkResults r;
  r.path = path;
  r.context = {{"mssph_cpu", cpu}, {"mssph_gpu", "none"}, {"mssph_build_type", "Release"}};
  for (const auto& [name, seconds] : times) {
    r.names.push_back(name);
    r.seconds[name] = seconds;
  }
  return r;
}

const std::vector<double> kBase{1.00, 1.02, 0.98, 1.01, 0.99, 1.03};

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out;
  for (double x : v) out.push_back(x * factor);
  return out;
}

TEST(BenchComparison, VerdictsFollowThresholdAndSignificance) {
  const BenchmarkResults base =
      results("a.json", {{"two_x", kBase}, {"same", kBase}, {"fast", kBase}, {"five_pct", kBase}});
  const BenchmarkResults cur = results("b.json", {{"two_x", scaled(kBase, 2.0)},
                                                  {"same", {1.01, 0.99, 1.0, 1.02, 0.985, 1.015}},
                                                  {"fast", scaled(kBase, 0.5)},
                                                  {"five_pct", scaled(kBase, 1.05)}});
  const ComparisonReport report = compare(base, cur, CompareOptions{});
  ASSERT_EQ(report.benchmarks.size(), 4u);
  EXPECT_EQ(report.benchmarks[0].verdict, Verdict::slower);
  EXPECT_NEAR(report.benchmarks[0].ratio, 2.0, 1e-12);
  EXPECT_NEAR(report.benchmarks[0].p_value, 2.0 / 924.0, 1e-12);  // complete separation, C(12, 6) = 924
  EXPECT_EQ(report.benchmarks[1].verdict, Verdict::unchanged);
  EXPECT_EQ(report.benchmarks[2].verdict, Verdict::faster);
  // 5 % slower, every repetition: significant, but within the 10 % threshold.
  EXPECT_EQ(report.benchmarks[3].verdict, Verdict::unchanged);
  EXPECT_LT(report.benchmarks[3].p_value, 0.05);
  EXPECT_TRUE(report.failed());
  EXPECT_FALSE(report.smallest_attainable_p.has_value());
}

TEST(BenchComparison, SlowerButNotSignificantDoesNotFail) {
  // Median 1.5x, but the samples overlap: one outlier-heavy run is no evidence.
  const ComparisonReport report = compare(results("a", {{"b", {1.0, 3.0, 1.0, 3.0, 1.0}}}),
                                          results("b", {{"b", {1.5, 1.1, 3.1, 0.9, 2.9}}}), CompareOptions{});
  EXPECT_EQ(report.benchmarks[0].verdict, Verdict::not_significant);
  EXPECT_FALSE(report.failed());
}

TEST(BenchComparison, TooFewRepetitionsAreSaidSo) {
  const ComparisonReport report =
      compare(results("a", {{"b", {1.0, 1.0, 1.0}}}), results("b", {{"b", {2.0, 2.1, 2.2}}}), CompareOptions{});
  EXPECT_EQ(report.benchmarks[0].verdict, Verdict::untestable);
  ASSERT_TRUE(report.smallest_attainable_p.has_value());
  EXPECT_NEAR(*report.smallest_attainable_p, 0.1, 1e-12);
  EXPECT_FALSE(report.failed());
  EXPECT_NE(format_report(report, ReportFormat::table).find("Too few repetitions"), std::string::npos);
}

TEST(BenchComparison, RefusesDifferentMachinesUnlessForced) {
  const BenchmarkResults base = results("a.json", {{"b", kBase}}, "Intel Xeon (2 threads)");
  const BenchmarkResults cur = results("b.json", {{"b", kBase}}, "AMD EPYC (2 threads)");
  try {
    compare(base, cur, CompareOptions{});
    FAIL() << "different CPUs compared";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("mssph_cpu"), std::string::npos) << message;
    EXPECT_NE(message.find("Intel Xeon (2 threads)"), std::string::npos) << message;
    EXPECT_NE(message.find("--force"), std::string::npos) << message;
    EXPECT_EQ(message.find("mssph_build_type"), std::string::npos) << message;
  }
  CompareOptions forced;
  forced.force = true;
  const ComparisonReport report = compare(base, cur, forced);
  ASSERT_EQ(report.machine_differences.size(), 1u);
  EXPECT_EQ(report.machine_differences[0].key, "mssph_cpu");
}

// A machine that takes 1.4 times as long for the current file: its calibration benchmark and an
// unchanged benchmark take 1.4 times as long, a benchmark whose code got 30 % slower 1.82 times.
// Raw, both fail the gate; normalized by the calibration, only the real slowdown does, and the
// calibration itself is not compared.
TEST(BenchComparison, NormalizingDividesOutTheMachinesSpeed) {
  const BenchmarkResults base =
      results("a.json", {{"calibration", kBase}, {"same_code", kBase}, {"slower_code", kBase}});
  const BenchmarkResults cur = results("b.json", {{"calibration", scaled(kBase, 1.4)},
                                                  {"same_code", scaled(kBase, 1.4)},
                                                  {"slower_code", scaled(kBase, 1.4 * 1.3)}});
  const ComparisonReport raw = compare(base, cur, CompareOptions{});
  ASSERT_EQ(raw.benchmarks.size(), 3u);
  EXPECT_EQ(raw.benchmarks[1].verdict, Verdict::slower);
  EXPECT_EQ(raw.benchmarks[2].verdict, Verdict::slower);

  CompareOptions options;
  options.normalize_by = "calibration";
  const ComparisonReport report = compare(base, cur, options);
  ASSERT_TRUE(report.normalization.has_value());
  EXPECT_NEAR(report.normalization->machine_ratio(), 1.4, 1e-12);
  ASSERT_EQ(report.benchmarks.size(), 2u);
  EXPECT_EQ(report.benchmarks[0].name, "same_code");
  EXPECT_NEAR(report.benchmarks[0].ratio, 1.0, 1e-12);
  EXPECT_EQ(report.benchmarks[0].verdict, Verdict::unchanged);
  EXPECT_NEAR(report.benchmarks[0].current_median, 1.4 * median(kBase), 1e-12);  // shown as measured
  EXPECT_EQ(report.benchmarks[1].name, "slower_code");
  EXPECT_NEAR(report.benchmarks[1].ratio, 1.3, 1e-12);
  EXPECT_EQ(report.benchmarks[1].verdict, Verdict::slower);
  EXPECT_TRUE(report.only_in_baseline.empty());
  EXPECT_TRUE(report.only_in_current.empty());
  EXPECT_NE(format_report(report, ReportFormat::table).find("Normalized by calibration"), std::string::npos);
  const nlohmann::json doc = nlohmann::json::parse(format_report(report, ReportFormat::json));
  EXPECT_NEAR(doc["normalized_by"]["machine_ratio"].get<double>(), 1.4, 1e-12);
}

TEST(BenchComparison, NormalizingNeedsTheCalibrationInBothFiles) {
  CompareOptions options;
  options.normalize_by = "calibration";
  try {
    compare(results("a.json", {{"calibration", kBase}, {"b", kBase}}), results("b.json", {{"b", kBase}}), options);
    FAIL() << "compared without the calibration in the current file";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("b.json"), std::string::npos) << message;
    EXPECT_NE(message.find("\"calibration\""), std::string::npos) << message;
  }
}

TEST(BenchComparison, NoCommonBenchmarkIsBadInput) {
  EXPECT_THROW(compare(results("a", {{"x", kBase}}), results("b", {{"y", kBase}}), CompareOptions{}), InputError);
}

TEST(BenchComparison, MedianOfOddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
}

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(BenchmarkResultsFile, ReadsRepetitionsAndSkipsAggregates) {
  const test::TempDir dir;
  const nlohmann::json doc = {
      {"context", {{"mssph_cpu", "X"}, {"num_cpus", 2}}},
      {"benchmarks",
       {{{"name", "t"}, {"run_name", "t"}, {"run_type", "iteration"}, {"real_time", 2.0}, {"time_unit", "ms"}},
        {{"name", "t"}, {"run_name", "t"}, {"run_type", "iteration"}, {"real_time", 4.0}, {"time_unit", "ms"}},
        {{"name", "t_mean"}, {"run_name", "t"}, {"run_type", "aggregate"}, {"real_time", 3.0}, {"time_unit", "ms"}},
        {{"name", "s/manual_time"},
         {"run_name", "s/manual_time"},
         {"run_type", "iteration"},
         {"real_time", 50.0},
         {"time_unit", "us"},
         {"step_seconds", 1e-6}},
        {{"name", "e"}, {"run_type", "iteration"}, {"error_occurred", true}, {"error_message", "no GPU"}}}}};
  write(dir / "r.json", doc.dump());
  const BenchmarkResults r = read_benchmark_results((dir / "r.json").string());
  EXPECT_EQ(r.context.at("mssph_cpu"), "X");
  EXPECT_EQ(r.context.at("num_cpus"), "2");
  ASSERT_EQ(r.names, (std::vector<std::string>{"t", "s/manual_time"}));
  EXPECT_EQ(r.seconds.at("t"), (std::vector<double>{2e-3, 4e-3}));
  EXPECT_EQ(r.seconds.at("s/manual_time"), (std::vector<double>{1e-6}));  // per step, not per batch
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("no GPU"), std::string::npos);
}

TEST(BenchmarkResultsFile, BadFilesNameTheFileAndTheProblem) {
  const test::TempDir dir;
  write(dir / "text.json", "not json");
  write(dir / "object.json", R"({"a": 1})");
  write(dir / "unit.json", R"({"context": {}, "benchmarks": [{"name": "t", "real_time": 1, "time_unit": "hours"}]})");
  const auto message_of = [&](const std::string& name) {
    try {
      read_benchmark_results((dir / name).string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of("missing.json").find("missing.json: cannot open"), std::string::npos);
  EXPECT_NE(message_of("text.json").find("text.json: not JSON"), std::string::npos);
  EXPECT_NE(message_of("object.json").find("no \"context\" object"), std::string::npos);
  EXPECT_NE(message_of("unit.json").find("/benchmarks/0/time_unit"), std::string::npos);
}

// Google Benchmark's file for two repetitions of a benchmark whose counter is zero in both: the
// counter's coefficient of variation is written as NaN, which no JSON reader takes, until those
// values are made null. Strings holding the same text keep it, after an escaped quote too.
TEST(BenchmarkResultsFile, ValuesWithoutAJsonLiteralBecomeNull) {
  const test::TempDir dir;
  const std::string entry = R"({"name": "t", "run_name": "t", "run_type": "iteration", "real_time": 2, )"
                            R"("time_unit": "ms", "builds": 0})";
  // As Google Benchmark lays an entry out: a key a line, indented.
  const std::string aggregate =
      "{\n      \"name\": \"t_cv\",\n      \"run_name\": \"t\",\n      \"run_type\": \"aggregate\",\n"
      "      \"real_time\": 0.1,\n      \"time_unit\": \"ms\",\n      \"builds\": NaN,\n"
      "      \"low\": -Infinity,\n      \"high\": Infinity\n    }";
  const std::string text = R"({"context": {"note": "a \": NaN, b", "label": ": NaN, x"}, "benchmarks": [)" + entry +
                           ",\n" + entry + ",\n    " + aggregate + "\n  ]\n}\n";
  write(dir / "r.json", text);
  EXPECT_THROW(read_benchmark_results((dir / "r.json").string()), InputError);
  null_for_values_without_json_literal((dir / "r.json").string());
  std::ifstream in(dir / "r.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  const nlohmann::json& cv = doc["benchmarks"][2];
  EXPECT_TRUE(cv["builds"].is_null());
  EXPECT_TRUE(cv["low"].is_null());
  EXPECT_TRUE(cv["high"].is_null());
  EXPECT_EQ(doc["context"]["note"], "a \": NaN, b");
  EXPECT_EQ(doc["context"]["label"], ": NaN, x");
  EXPECT_EQ(read_benchmark_results((dir / "r.json").string()).seconds.at("t"), (std::vector<double>{2e-3, 2e-3}));
}

// A time of zero or below, or an instruction count that is not positive, is not a measurement.
TEST(BenchmarkResultsFile, NonPositiveTimesAndCountsAreBadInput) {
  const test::TempDir dir;
  const std::string head = R"({"context": {}, "benchmarks": [{"name": "t", "time_unit": "ms", )";
  write(dir / "zero.json", head + R"("real_time": 0}]})");
  write(dir / "negative.json", head + R"("real_time": -1}]})");
  write(dir / "count.json", head + R"("real_time": 1, "instructions_per_step": 0}]})");
  for (const char* name : {"zero.json", "negative.json", "count.json"}) {
    try {
      read_benchmark_results((dir / name).string());
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected a positive finite number"), std::string::npos) << e.what();
    }
  }
}

// With counts (mssph bench --count-instructions) the instruction gate fails on any rise beyond
// its threshold, noisy wall times or not; a file without counts cannot be judged.
TEST(BenchComparison, InstructionGateJudgesCountsNotTimes) {
  BenchmarkResults base = results("a.json", {{"five_pct", kBase}, {"two_pct", kBase}, {"wall_only", kBase}});
  BenchmarkResults cur = results(
      "b.json", {{"five_pct", scaled(kBase, 0.5)}, {"two_pct", scaled(kBase, 3.0)}, {"wall_only", scaled(kBase, 3.0)}});
  base.instructions_per_step = {{"five_pct", 1e6}, {"two_pct", 1e6}, {"wall_only", 1e6}};
  cur.instructions_per_step = {{"five_pct", 1.05e6}, {"two_pct", 1.02e6}, {"wall_only", 1e6}};
  CompareOptions options;
  options.gate = GateMeasure::instructions;
  options.threshold = 0.03;
  const ComparisonReport report = compare(base, cur, options);
  ASSERT_EQ(report.benchmarks.size(), 3u);
  EXPECT_EQ(report.benchmarks[0].verdict, Verdict::slower);  // faster on the clock, more work
  EXPECT_NEAR(*report.benchmarks[0].instruction_ratio, 1.05, 1e-12);
  EXPECT_EQ(report.benchmarks[1].verdict, Verdict::unchanged);
  EXPECT_EQ(report.benchmarks[2].verdict, Verdict::unchanged);  // 3x the wall time, the same work
  EXPECT_TRUE(report.failed());
  const std::string text = format_report(report, ReportFormat::table);
  EXPECT_NE(text.find("instr ratio"), std::string::npos) << text;
  EXPECT_NE(text.find("gate is on instructions per step"), std::string::npos) << text;

  cur.instructions_per_step.erase("two_pct");
  try {
    compare(base, cur, options);
    ADD_FAILURE() << "a benchmark without counts was judged";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.json: no instructions_per_step for two_pct"), std::string::npos)
        << e.what();
  }
}

// Instruction counts do not depend on the machine's speed: files of different CPUs compare, but
// not of different compilers.
TEST(BenchComparison, InstructionGateChecksTheBuildNotTheCpu) {
  BenchmarkResults base = results("a.json", {{"s", kBase}}, "CPU one");
  BenchmarkResults cur = results("b.json", {{"s", kBase}}, "CPU two");
  base.instructions_per_step = cur.instructions_per_step = {{"s", 1e6}};
  base.context["mssph_compiler"] = cur.context["mssph_compiler"] = "GNU 12.2.0";
  CompareOptions options;
  options.gate = GateMeasure::instructions;
  EXPECT_FALSE(compare(base, cur, options).failed());
  cur.context["mssph_compiler"] = "Clang 14";
  EXPECT_THROW(compare(base, cur, options), InputError);
}

}  // namespace
}  // namespace mssph::bench
