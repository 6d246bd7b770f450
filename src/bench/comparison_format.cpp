#include "bench/comparison_format.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace mssph::bench {
namespace {

// A time with a unit that keeps three to four significant digits.
std::string format_time(double seconds) {
  const char* unit = "s";
  double value = seconds;
  if (seconds < 1e-6) {
    value = seconds * 1e9;
    unit = "ns";
  } else if (seconds < 1e-3) {
    value = seconds * 1e6;
    unit = "us";
  } else if (seconds < 1.0) {
    value = seconds * 1e3;
    unit = "ms";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g %s", value, unit);
  return buffer;
}

std::string format_number(const char* pattern, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string percent(double fraction) { return format_number("%.0f%%", 100.0 * fraction); }

bool has_counts(const ComparisonReport& report) {
  return std::any_of(report.benchmarks.begin(), report.benchmarks.end(),
                     [](const BenchmarkComparison& b) { return b.instruction_ratio.has_value(); });
}

std::string count_or_dash(const std::optional<double>& value, const char* pattern) {
  return value ? format_number(pattern, *value) : "-";
}

// One row per benchmark: wall time (medians, ratio, test), then the instruction counts where both
// files have them, then the verdict on the gate's measure.
std::vector<std::vector<std::string>> rows_of(const ComparisonReport& report) {
  const bool counts = has_counts(report);
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header{"benchmark", "baseline", "current", "ratio", "p", "n"};
  if (counts) header.insert(header.end(), {"instr/step", "instr ratio", "LL misses/step"});
  header.push_back("verdict");
  rows.push_back(header);
  for (const BenchmarkComparison& b : report.benchmarks) {
    std::vector<std::string> row{b.name,
                                 format_time(b.baseline_median),
                                 format_time(b.current_median),
                                 format_number("%.3f", b.ratio),
                                 format_number("%.3g", b.p_value),
                                 std::to_string(b.baseline_repetitions) + "/" + std::to_string(b.current_repetitions)};
    if (counts) {
      row.insert(row.end(), {count_or_dash(b.current_instructions, "%.4g"), count_or_dash(b.instruction_ratio, "%.4f"),
                             count_or_dash(b.current_ll_misses, "%.3g")});
    }
    row.push_back(to_string(b.verdict));
    rows.push_back(row);
  }
  return rows;
}

// Lines that explain the numbers: the test, the gate's rule, the caveats.
std::vector<std::string> notes_of(const ComparisonReport& report) {
  const CompareOptions& o = report.options;
  std::vector<std::string> notes;
  notes.push_back("baseline " + report.baseline_path + ", current " + report.current_path +
                  "; times are medians over repetitions (per step where the benchmark reports step_seconds), ratio = "
                  "current / baseline.");
  notes.push_back(
      "p: two-sided Mann-Whitney U test over the repetitions (exact without ties and with at most 20 "
      "per side, else normal approximation with tie and continuity correction); significant when p < " +
      format_number("%g", o.alpha) + ".");
  if (report.normalization) {
    const Normalization& n = *report.normalization;
    notes.push_back(
        "Normalized by " + n.name +
        " (a fixed workload that times the machine): the current file's machine ran it in " +
        format_time(n.current_median) + " against the baseline's " + format_time(n.baseline_median) + " (" +
        format_number("%.3f", n.machine_ratio()) +
        "x); each ratio and test is of the current times divided by that factor, the medians shown are as measured.");
  }
  if (has_counts(report)) {
    notes.push_back(
        "instr/step: instructions executed per step (or tick) in the current file, counted by Callgrind; instr "
        "ratio = current / baseline; LL misses/step: simulated last-level cache misses per step.");
  }
  if (o.gate == GateMeasure::instructions) {
    notes.push_back(
        "The gate is on instructions per step, which other load on the machine does not change: it fails "
        "(exit 1) on a benchmark whose instruction ratio exceeds " +
        format_number("%.3f", 1.0 + o.threshold) + " (threshold " + percent(o.threshold) +
        "). Wall time is shown for information.");
  } else {
    notes.push_back("The gate fails (exit 1) on a benchmark whose ratio exceeds " +
                    format_number("%.3f", 1.0 + o.threshold) + " (threshold " + percent(o.threshold) +
                    ") with a significant difference.");
  }
  if (report.smallest_attainable_p && o.gate == GateMeasure::wall_time) {
    notes.push_back(
        "Too few repetitions for some benchmarks: with their counts the smallest p-value the test can give "
        "is " +
        format_number("%.3g", *report.smallest_attainable_p) +
        ", not below alpha, so no difference there can be significant; run more repetitions "
        "(at least 4 per side for alpha 0.05).");
  }
  for (const ContextDifference& d : report.machine_differences) {
    notes.push_back("forced: " + d.key + " differs (baseline \"" + d.baseline + "\", current \"" + d.current + "\").");
  }
  for (const std::string& name : report.only_in_baseline) notes.push_back("only in the baseline: " + name);
  for (const std::string& name : report.only_in_current) notes.push_back("only in the current file: " + name);
  for (const std::string& e : report.errors) notes.push_back("error reported by the benchmark: " + e);
  const char* failure = o.gate == GateMeasure::instructions ? "FAIL, more instructions per step beyond the threshold."
                                                            : "FAIL, significantly slower beyond the threshold.";
  notes.push_back(std::string("Result: ") + (report.failed() ? failure : "pass."));
  return notes;
}

std::string as_table(const ComparisonReport& report) {
  const auto rows = rows_of(report);
  std::vector<std::size_t> widths(rows.front().size(), 0);
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  std::ostringstream out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      const std::string& cell = rows[r][c];
      const std::string pad(widths[c] - cell.size(), ' ');
      // Names and verdicts left-aligned, numbers right-aligned.
      const bool left = c == 0 || c + 1 == rows[r].size();
      out << (c ? "  " : "") << (left ? cell + pad : pad + cell);
    }
    out << "\n";
  }
  out << "\n";
  for (const std::string& note : notes_of(report)) out << note << "\n";
  return out.str();
}

std::string as_markdown(const ComparisonReport& report) {
  const auto rows = rows_of(report);
  std::ostringstream out;
  out << "### mssph bench compare: " << (report.failed() ? "FAIL" : "pass") << "\n\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out << "|";
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      const bool highlight = r > 0 && report.benchmarks[r - 1].verdict == Verdict::slower && c + 1 == rows[r].size();
      out << " "
          << (c == 0 && r > 0 ? "`" + rows[r][c] + "`"
              : highlight     ? "**" + rows[r][c] + "**"
                              : rows[r][c])
          << " |";
    }
    out << "\n";
    if (r == 0) {
      out << "|";
      for (std::size_t c = 0; c < rows[r].size(); ++c)
        out << (c == 0 || c + 1 == rows[r].size() ? " --- |" : " ---: |");
      out << "\n";
    }
  }
  out << "\n";
  for (const std::string& note : notes_of(report)) out << "- " << note << "\n";
  return out.str();
}

nlohmann::json json_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string as_json(const ComparisonReport& report) {
  nlohmann::json doc;
  doc["baseline"] = report.baseline_path;
  doc["current"] = report.current_path;
  doc["threshold"] = report.options.threshold;
  doc["alpha"] = report.options.alpha;
  doc["test"] = "two-sided Mann-Whitney U";
  doc["gate"] = report.options.gate == GateMeasure::instructions ? "instructions" : "wall time";
  doc["failed"] = report.failed();
  doc["benchmarks"] = nlohmann::json::array();
  for (const BenchmarkComparison& b : report.benchmarks) {
    doc["benchmarks"].push_back({{"name", b.name},
                                 {"baseline_median_seconds", b.baseline_median},
                                 {"current_median_seconds", b.current_median},
                                 {"baseline_repetitions", b.baseline_repetitions},
                                 {"current_repetitions", b.current_repetitions},
                                 {"ratio", b.ratio},
                                 {"u", b.u},
                                 {"p_value", b.p_value},
                                 {"exact", b.exact},
                                 {"baseline_instructions_per_step", json_or_null(b.baseline_instructions)},
                                 {"current_instructions_per_step", json_or_null(b.current_instructions)},
                                 {"instruction_ratio", json_or_null(b.instruction_ratio)},
                                 {"baseline_ll_misses_per_step", json_or_null(b.baseline_ll_misses)},
                                 {"current_ll_misses_per_step", json_or_null(b.current_ll_misses)},
                                 {"verdict", to_string(b.verdict)}});
  }
  doc["only_in_baseline"] = report.only_in_baseline;
  doc["only_in_current"] = report.only_in_current;
  doc["errors"] = report.errors;
  doc["forced_differences"] = nlohmann::json::array();
  for (const ContextDifference& d : report.machine_differences) {
    doc["forced_differences"].push_back({{"key", d.key}, {"baseline", d.baseline}, {"current", d.current}});
  }
  if (report.normalization) {
    const Normalization& n = *report.normalization;
    doc["normalized_by"] = {{"name", n.name},
                            {"baseline_median_seconds", n.baseline_median},
                            {"current_median_seconds", n.current_median},
                            {"machine_ratio", n.machine_ratio()}};
  } else {
    doc["normalized_by"] = nullptr;
  }
  doc["smallest_attainable_p"] =
      report.smallest_attainable_p ? nlohmann::json(*report.smallest_attainable_p) : nlohmann::json(nullptr);
  return doc.dump(2) + "\n";
}

}  // namespace

std::string format_report(const ComparisonReport& report, ReportFormat format) {
  switch (format) {
    case ReportFormat::table:
      return as_table(report);
    case ReportFormat::markdown:
      return as_markdown(report);
    case ReportFormat::json:
      return as_json(report);
  }
  return {};
}

}  // namespace mssph::bench
