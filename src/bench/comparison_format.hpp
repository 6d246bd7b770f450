#pragma once
// The three renderings of a comparison: an aligned text table for a terminal, a markdown table
// for a CI job summary, and JSON for tools.
#include "bench/bench_comparison.hpp"

#include <string>

namespace mssph::bench {

enum class ReportFormat { table, markdown, json };

std::string format_report(const ComparisonReport& report, ReportFormat format);

}  // namespace mssph::bench
