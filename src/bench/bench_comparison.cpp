#include "bench/bench_comparison.hpp"

#include "bench/mann_whitney.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <stdexcept>

namespace mssph::bench {
namespace {

std::string context_value(const BenchmarkResults& results, const std::string& key) {
  const auto it = results.context.find(key);
  return it == results.context.end() ? "(not recorded)" : it->second;
}

// machine_ratio: how much slower the current file's machine ran (1 without normalization); the
// current times are divided by it for the ratio and the test, the medians shown stay as measured.
BenchmarkComparison compare_one(const std::string& name, const std::vector<double>& baseline,
                                const std::vector<double>& current, double machine_ratio, const CompareOptions& options,
                                std::optional<double>& smallest_attainable_p) {
  BenchmarkComparison c;
  c.name = name;
  c.baseline_repetitions = baseline.size();
  c.current_repetitions = current.size();
  c.baseline_median = median(baseline);
  c.current_median = median(current);
  std::vector<double> adjusted = current;
  for (double& t : adjusted) t /= machine_ratio;
  c.ratio = median(adjusted) / c.baseline_median;
  const MannWhitneyResult test = mann_whitney_u(adjusted, baseline);
  c.u = test.u;
  c.p_value = test.p_value;
  c.exact = test.exact;
  const double floor_p = smallest_p_value(current.size(), baseline.size());
  const bool significant = c.p_value < options.alpha;
  if (c.ratio > 1.0 + options.threshold) {
    c.verdict = significant ? Verdict::slower : Verdict::not_significant;
  } else if (c.ratio < 1.0 / (1.0 + options.threshold)) {
    c.verdict = significant ? Verdict::faster : Verdict::not_significant;
  } else {
    c.verdict = Verdict::unchanged;
  }
  if (floor_p >= options.alpha) {
    smallest_attainable_p = std::min(smallest_attainable_p.value_or(1.0), floor_p);
    if (c.verdict == Verdict::not_significant) c.verdict = Verdict::untestable;
  }
  return c;
}

std::optional<double> find(const std::map<std::string, double>& values, const std::string& name) {
  const auto it = values.find(name);
  return it == values.end() ? std::nullopt : std::optional<double>(it->second);
}

// Adds the instruction counts of both files; on the instruction gate, the verdict is theirs: a
// count is exact, so any rise beyond the threshold is a regression.
void add_instructions(BenchmarkComparison& c, const BenchmarkResults& baseline, const BenchmarkResults& current,
                      const CompareOptions& options) {
  c.baseline_instructions = find(baseline.instructions_per_step, c.name);
  c.current_instructions = find(current.instructions_per_step, c.name);
  c.baseline_ll_misses = find(baseline.ll_misses_per_step, c.name);
  c.current_ll_misses = find(current.ll_misses_per_step, c.name);
  if (c.baseline_instructions && c.current_instructions) {
    c.instruction_ratio = *c.current_instructions / *c.baseline_instructions;
  }
  if (options.gate != GateMeasure::instructions) return;
  if (!c.instruction_ratio) {
    const std::string& path = c.baseline_instructions ? current.path : baseline.path;
    throw InputError(path + ": no instructions_per_step for " + c.name +
                     " (the instruction gate needs both files made by `mssph bench --count-instructions`)");
  }
  const double r = *c.instruction_ratio;
  c.verdict = r > 1.0 + options.threshold           ? Verdict::slower
              : r < 1.0 / (1.0 + options.threshold) ? Verdict::faster
                                                    : Verdict::unchanged;
}

Normalization normalization(const BenchmarkResults& baseline, const BenchmarkResults& current,
                            const std::string& name) {
  Normalization n{name, 0.0, 0.0};
  for (const BenchmarkResults* file : {&baseline, &current}) {
    const auto it = file->seconds.find(name);
    if (it == file->seconds.end()) {
      throw InputError(file->path + ": no benchmark \"" + name +
                       "\" to normalize by (--normalize-by); "
                       "run it with the others, e.g. --filter '...|^" +
                       name + "$'");
    }
    const double m = median(it->second);
    if (!(m > 0.0)) throw InputError(file->path + ": benchmark \"" + name + "\" has no positive time to normalize by");
    (file == &baseline ? n.baseline_median : n.current_median) = m;
  }
  return n;
}

}  // namespace

const char* to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::slower:
      return "SLOWER";
    case Verdict::faster:
      return "faster";
    case Verdict::unchanged:
      return "unchanged";
    case Verdict::not_significant:
      return "not significant";
    case Verdict::untestable:
      return "too few repetitions";
  }
  return "?";
}

bool ComparisonReport::failed() const {
  return std::any_of(benchmarks.begin(), benchmarks.end(), [](const auto& b) { return b.verdict == Verdict::slower; });
}

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<ContextDifference> machine_differences(const BenchmarkResults& baseline, const BenchmarkResults& current,
                                                   const std::vector<std::string>& keys) {
  std::vector<ContextDifference> differences;
  for (const std::string& key : keys) {
    const std::string a = context_value(baseline, key);
    const std::string b = context_value(current, key);
    if (a != b) differences.push_back({key, a, b});
  }
  return differences;
}

ComparisonReport compare(const BenchmarkResults& baseline, const BenchmarkResults& current,
                         const CompareOptions& options) {
  ComparisonReport report;
  report.baseline_path = baseline.path;
  report.current_path = current.path;
  report.options = options;
  const bool counts = options.gate == GateMeasure::instructions;
  report.machine_differences = machine_differences(baseline, current, counts ? kInstructionKeys : kMachineKeys);
  if (!report.machine_differences.empty() && !options.force) {
    std::string message = counts ? "the files come from different builds, whose instruction counts do not compare:"
                                 : "the files come from different machines or builds, whose times do not compare:";
    for (const ContextDifference& d : report.machine_differences) {
      message += "\n  " + d.key + ": baseline \"" + d.baseline + "\", current \"" + d.current + "\"";
    }
    throw InputError(message + "\n(--force compares them anyway)");
  }
  double machine_ratio = 1.0;
  if (options.normalize_by) {
    report.normalization = normalization(baseline, current, *options.normalize_by);
    machine_ratio = report.normalization->machine_ratio();
  }
  const auto is_yardstick = [&](const std::string& name) {
    return options.normalize_by && name == *options.normalize_by;
  };
  for (const std::string& name : baseline.names) {
    if (is_yardstick(name)) continue;
    const auto it = current.seconds.find(name);
    if (it == current.seconds.end()) {
      report.only_in_baseline.push_back(name);
      continue;
    }
    report.benchmarks.push_back(
        compare_one(name, baseline.seconds.at(name), it->second, machine_ratio, options, report.smallest_attainable_p));
    add_instructions(report.benchmarks.back(), baseline, current, options);
  }
  for (const std::string& name : current.names) {
    if (!baseline.seconds.count(name) && !is_yardstick(name)) report.only_in_current.push_back(name);
  }
  for (const std::string& e : baseline.errors) report.errors.push_back(baseline.path + ": " + e);
  for (const std::string& e : current.errors) report.errors.push_back(current.path + ": " + e);
  if (report.benchmarks.empty()) {
    throw InputError(baseline.path + " and " + current.path + " have no benchmark in common");
  }
  return report;
}

}  // namespace mssph::bench
