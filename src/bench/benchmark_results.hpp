#pragma once
// A Google Benchmark JSON file (--benchmark_out_format=json) as `mssph bench compare` reads it:
// the machine context and, per benchmark, the real time of each repetition.
#include <map>
#include <string>
#include <vector>

namespace mssph::bench {

// The context keys that say which machine and build made a file: files that differ in any of
// them do not compare (`mssph bench` writes them; see benchmarks/machine_context.cpp).
inline const std::vector<std::string> kMachineKeys{"mssph_cpu", "mssph_gpu", "mssph_build_type"};

struct BenchmarkResults {
  std::string path;
  std::map<std::string, std::string> context;  // the file's "context", values as text
  // Per benchmark, in the order of the file: the time of each repetition [s], per step where the
  // entry has a step_seconds counter (step/ and scene/ benchmarks), else the real time per
  // iteration. Aggregates
  // (mean, median, stddev) are left out: the test needs the repetitions themselves.
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> seconds;
  // Per benchmark counted by `mssph bench --count-instructions`: instructions executed and
  // simulated last-level cache misses per step (or tick), the same in every repetition.
  std::map<std::string, double> instructions_per_step;
  std::map<std::string, double> ll_misses_per_step;
  std::vector<std::string> errors;  // benchmarks that reported an error, with its message
};

// Throws InputError naming the file and what is wrong: unreadable, not JSON, not Google Benchmark
// output (no "context" object or "benchmarks" array), an entry without name, time or unit, a
// time or count that is not a positive finite number; duplicate keys, numbers beyond a double and
// deep nesting, as for every JSON file mssph reads (config/strict_json.hpp).
BenchmarkResults read_benchmark_results(const std::string& path);

// Google Benchmark writes a value it cannot compute as NaN or (-)Infinity, which JSON has no
// literal for: the coefficient of variation of a counter that is zero in every repetition is
// 0 / 0. Rewrites the file at `path` with null for each such value (never text inside a string),
// so that every JSON reader takes it. Throws InputError when the file cannot be read (as
// read_input_file) and std::runtime_error when it cannot be written.
void null_for_values_without_json_literal(const std::string& path);

}  // namespace mssph::bench
