#pragma once
// `mssph bench compare`: per benchmark common to a baseline and a current result file, the ratio
// of median times, a two-sided Mann-Whitney U test over the repetitions, and a verdict. The gate
// is on one of two measures:
// - wall time: it fails only on a slowdown that is both larger than the threshold and
//   significant, so that a noisy machine alone does not fail it (a quiet, dedicated machine; GPUs);
// - instructions per step, counted by Callgrind (`mssph bench --count-instructions`): the same
//   for the same build and inputs whatever else the machine runs, so a rise beyond the threshold
//   fails it with no test needed (a shared CI runner). Wall time is then reported beside it.
#include "bench/benchmark_results.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mssph::bench {

enum class GateMeasure { wall_time, instructions };

struct CompareOptions {
  GateMeasure gate = GateMeasure::wall_time;
  double threshold = 0.10;  // a slowdown beyond ratio 1 + threshold (of the gate's measure) can fail the gate
  double alpha = 0.05;      // significance level of the test
  bool force = false;       // compare files from different machines or build types anyway
  // A benchmark of both files that times the machine, not the code (calibration/cpu): each file's
  // times are divided by its median before the ratios and tests, and it is not compared itself.
  std::optional<std::string> normalize_by;
};

// How much slower the current file's machine ran the calibration benchmark (normalize_by).
struct Normalization {
  std::string name;
  double baseline_median = 0.0;  // [s]
  double current_median = 0.0;   // [s]
  double machine_ratio() const { return current_median / baseline_median; }
};

enum class Verdict {
  slower,           // ratio > 1 + threshold and significant: fails the gate
  faster,           // ratio < 1 / (1 + threshold) and significant
  unchanged,        // within the threshold (significant or not)
  not_significant,  // beyond the threshold but not significant: noise cannot be ruled out
  untestable        // fewer repetitions than the test can decide on
};
const char* to_string(Verdict verdict);

struct BenchmarkComparison {
  std::string name;
  std::size_t baseline_repetitions = 0;
  std::size_t current_repetitions = 0;
  double baseline_median = 0.0;  // [s]
  double current_median = 0.0;   // [s]
  double ratio = 0.0;            // current / baseline median, divided by the machine ratio when normalized
  double u = 0.0;                // Mann-Whitney U of the current sample
  double p_value = 1.0;
  bool exact = false;
  // Instructions per step in each file, and their ratio, where both files counted them.
  std::optional<double> baseline_instructions, current_instructions;
  std::optional<double> instruction_ratio;
  std::optional<double> baseline_ll_misses, current_ll_misses;  // simulated last-level misses per step
  Verdict verdict = Verdict::unchanged;                         // on the gate's measure
};

// A machine context key whose values differ between the files.
struct ContextDifference {
  std::string key;
  std::string baseline;
  std::string current;
};

struct ComparisonReport {
  std::string baseline_path;
  std::string current_path;
  CompareOptions options;
  std::vector<ContextDifference> machine_differences;  // only compared under --force
  std::optional<Normalization> normalization;          // with options.normalize_by
  std::vector<BenchmarkComparison> benchmarks;
  std::vector<std::string> only_in_baseline;
  std::vector<std::string> only_in_current;
  std::vector<std::string> errors;  // benchmarks that failed in either file
  // When some benchmark's repetitions are too few for any difference to be significant: the
  // smallest p-value its sizes allow, for the note in the output.
  std::optional<double> smallest_attainable_p;

  bool failed() const;  // any verdict "slower"
};

// The context keys whose values differ: kMachineKeys for wall time; for instruction counts, which
// do not depend on the machine's speed, kInstructionKeys (the build and its compiler).
inline const std::vector<std::string> kInstructionKeys{"mssph_build_type", "mssph_compiler"};
std::vector<ContextDifference> machine_differences(const BenchmarkResults& baseline, const BenchmarkResults& current,
                                                   const std::vector<std::string>& keys = kMachineKeys);

// Throws InputError when the files share no benchmark, when a file lacks options.normalize_by or
// its times are not positive, when the gate is on instructions and a common benchmark lacks
// counts in either file, or, without options.force, when their machine context differs (the
// message names each differing key and both values).
ComparisonReport compare(const BenchmarkResults& baseline, const BenchmarkResults& current,
                         const CompareOptions& options);

double median(std::vector<double> values);

}  // namespace mssph::bench
