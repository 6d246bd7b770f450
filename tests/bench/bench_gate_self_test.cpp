// The gate catches a known slowdown and passes the same build: real `mssph bench` runs of the
// smallest host benchmark (A, B, and one with the MSSPH_BENCH_STEP_DELAY_US test hook set to
// twice A's step time), compared through the real `mssph bench compare`. And a scene file's step.
#include "bench/bench_comparison.hpp"
#include "cli_fixture.hpp"

#include <cmath>
#include <iostream>

namespace mssph::test {
namespace {

// One thread: on a shared 2-core machine a second OpenMP thread waits on a busy core far more
// often than it helps, and the run-to-run spread is what this test must stay clear of.
const std::string kThreads = "OMP_NUM_THREADS=1";

class GateSelfTest : public Cli {
 protected:
  // Runs the 2000-particle fluid step on cpu: 8 repetitions (enough for p = 2/C(16, 8) = 1.6e-4
  // at complete separation), one batch of 50 steps each.
  ProcessResult bench(const std::string& out, const std::string& delay_us) const {
    std::vector<std::string> argv{"/usr/bin/env", kThreads};
    if (!delay_us.empty()) argv.push_back("MSSPH_BENCH_STEP_DELAY_US=" + delay_us);
    for (const std::string a : {MSSPH_BINARY, "bench", "--backend", "cpu", "--filter", "^step/cpu/fluid/2000/",
                                "--repetitions", "8", "--min-time", "0.01", "--out"}) {
      argv.push_back(a);
    }
    argv.push_back(work(out));
    ChildProcess child(argv, work_.path(), capture_.path());
    return child.wait(std::chrono::seconds(120));
  }
};

TEST_F(GateSelfTest, PassesTheSameBuildAndCatchesTheDelayedOne) {
  const ProcessResult a = bench("a.json", "");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const bench::BenchmarkResults first = bench::read_benchmark_results(work("a.json"));
  const std::string name = "step/cpu/fluid/2000/manual_time";
  ASSERT_EQ(first.seconds.count(name), 1u);
  ASSERT_EQ(first.seconds.at(name).size(), 8u);
  const double step = bench::median(first.seconds.at(name));
  ASSERT_GT(step, 0.0);
  const nlohmann::json context = read_json(work("a.json"))["context"];
  for (const std::string key : {"mssph_cpu", "mssph_cpu_cores", "mssph_gpu", "mssph_gpu_driver", "mssph_build_type",
                                "mssph_git_commit", "mssph_compiler"}) {
    EXPECT_TRUE(context.contains(key)) << key;
  }
  EXPECT_FALSE(context.contains("mssph_test_step_delay_us"));

  const std::string delay_us = std::to_string(std::lround(2.0 * step * 1e6));
  const ProcessResult d = bench("delayed.json", delay_us);
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_TRUE(read_json(work("delayed.json"))["context"].contains("mssph_test_step_delay_us"));

  // The delay is wall time added to every step, so the delayed run's ratio is 2 plus its own step
  // time over A's, whatever the load. The threshold of 50 % stays below that and above the spread
  // of two undelayed runs on a loaded 2-core VM (same-build median ratios of 0.73-1.37 were seen at
  // load average 10-13; results/decisions/025), and this test runs alone (RUN_SERIAL). B is
  // measured again when it fails, up to three runs: other load only adds time, so one passing run
  // shows the same build is not slower. The delayed run must fail its one comparison, so the
  // retries cannot hide a slowdown. (The CI gate itself judges instruction counts, below.)
  constexpr int kAttempts = 3;
  ProcessResult same;
  for (int attempt = 1; attempt <= kAttempts; ++attempt) {
    const ProcessResult b = bench("b.json", "");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    same = mssph({"bench", "compare", work("a.json"), work("b.json"), "--threshold", "50%"});
    if (same.exit_code == 0) break;
    std::cerr << "same-build run " << attempt << " of " << kAttempts << " failed the comparison:\n" << same.out;
  }
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  const ProcessResult slow =
      mssph({"bench", "compare", work("a.json"), work("delayed.json"), "--threshold", "50%", "--format", "json"});
  EXPECT_EQ(slow.exit_code, 1) << slow.out << slow.err;
  const nlohmann::json report = nlohmann::json::parse(slow.out);
  EXPECT_EQ(report["benchmarks"][0]["verdict"], "SLOWER");
  EXPECT_GT(report["benchmarks"][0]["ratio"].get<double>(), 2.0) << "delay " << delay_us << " us per step";
}

// The instruction gate: two runs of the same build count the same instructions per step to the
// last digit, so they compare at ratio 1 and pass; a run with one extra step every 20 (5 % more
// of the same work, MSSPH_BENCH_EXTRA_STEP_EVERY) fails the 3 % threshold. Counting needs Valgrind
// (Debian's valgrind package, which scripts/setup.sh installs).
TEST_F(GateSelfTest, InstructionCountsRepeatAndCatchFivePercentMoreWork) {
  if (run_process({"/bin/sh", "-c", "command -v valgrind"}, work_.path()).exit_code != 0) {
    GTEST_SKIP() << "valgrind is not installed: the instruction gate cannot count here";
  }
  const auto count = [&](const std::string& out, const std::string& extra_every) {
    std::vector<std::string> argv{"/usr/bin/env", kThreads};
    if (!extra_every.empty()) argv.push_back("MSSPH_BENCH_EXTRA_STEP_EVERY=" + extra_every);
    for (const std::string a : {MSSPH_BINARY, "bench", "--backend", "cpu", "--filter", "^step/cpu/fluid/2000/",
                                "--repetitions", "1", "--min-time", "0.01", "--count-instructions", "--out"}) {
      argv.push_back(a);
    }
    argv.push_back(work(out));
    return run_process(argv, work_.path());
  };
  for (const auto& [file, every] : {std::pair{"a.json", ""}, {"b.json", ""}, {"extra.json", "20"}}) {
    const ProcessResult r = count(file, every);
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
  }
  const std::string name = "step/cpu/fluid/2000/manual_time";
  const bench::BenchmarkResults a = bench::read_benchmark_results(work("a.json"));
  const bench::BenchmarkResults b = bench::read_benchmark_results(work("b.json"));
  ASSERT_EQ(a.instructions_per_step.count(name), 1u);
  EXPECT_GT(a.instructions_per_step.at(name), 1e6);  // a 2000-particle step is millions of instructions
  EXPECT_EQ(a.instructions_per_step.at(name), b.instructions_per_step.at(name));

  const ProcessResult same = mssph({"bench", "compare", work("a.json"), work("b.json"), "--gate", "instructions"});
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  const ProcessResult more =
      mssph({"bench", "compare", work("a.json"), work("extra.json"), "--gate", "instructions", "--format", "json"});
  EXPECT_EQ(more.exit_code, 1) << more.out << more.err;
  const nlohmann::json report = nlohmann::json::parse(more.out);
  EXPECT_EQ(report["gate"], "instructions");
  EXPECT_EQ(report["benchmarks"][0]["verdict"], "SLOWER");
  // The extra step is one particular step, the 41st since the scene was built, and its count
  // differs from the mean of the 20 counted ones: the cpu backend rebuilds its lists on some steps
  // (a walk of the grid) and keeps them on others, and a step that keeps them costs less than the
  // mean. So the ratio lies near 1.05, within 2 %, not at it (decision 093).
  EXPECT_NEAR(report["benchmarks"][0]["instruction_ratio"].get<double>(), 1.05, 0.02);
  EXPECT_TRUE(read_json(work("extra.json"))["context"].contains("mssph_test_extra_step_every"));
}

TEST_F(GateSelfTest, TimesOneStepOfASceneFile) {
  const ProcessResult r =
      run_process({"/usr/bin/env", kThreads, MSSPH_BINARY, "bench", data_file("tiny_drop.json"), "--backend", "cpu",
                   "--repetitions", "2", "--min-time", "0.01", "--out", work("scene.json")},
                  work_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const bench::BenchmarkResults results = bench::read_benchmark_results(work("scene.json"));
  ASSERT_EQ(results.names, std::vector<std::string>{"scene/cpu/tiny_drop/manual_time"});
  EXPECT_EQ(results.seconds.at("scene/cpu/tiny_drop/manual_time").size(), 2u);
}

}  // namespace
}  // namespace mssph::test
