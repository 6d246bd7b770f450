#pragma once
// What a validation case is and what it reports: rows of the table (one per checked quantity:
// expected, measured, error, tolerance, PASS/FAIL/SKIPPED) and raw series for the plots.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mssph::validation {

enum class Status { pass, fail, skipped };

const char* status_name(Status status);  // "PASS", "FAIL", "SKIPPED"

// One checked quantity. `error` is what `tolerance` bounds; how it is formed is in `error_kind`:
// "relative" |measured - expected| / |expected|, "absolute" |measured - expected|, "bound" the
// measured value itself against an upper bound (expected 0, e.g. a relative L2 difference), or
// "range" (expected_text gives [lo, hi]; error 0 inside, else the distance outside).
struct Check {
  std::string quantity;
  std::string unit;
  double expected = 0.0;
  std::string expected_text;  // how expected is shown, e.g. "1.5" or "<= 1e-05" or "[0.37, 0.39]"
  double measured = 0.0;
  double error = 0.0;
  std::string error_kind;
  double tolerance = 0.0;
  Status status = Status::fail;
  std::string note;     // SKIPPED: why; otherwise optional detail
  std::string backend;  // the backend the quantity was measured on
};

Check relative_check(std::string quantity, std::string unit, double expected, double measured, double tolerance);
Check absolute_check(std::string quantity, std::string unit, double expected, double measured, double tolerance);
Check bound_check(std::string quantity, std::string unit, double measured, double bound);
Check range_check(std::string quantity, std::string unit, double lower, double upper, double measured);
Check skipped_check(std::string quantity, std::string reason);

// A raw series: x and named y columns of the same length, stored in the report's HDF5 file
// under /<suite>/<case>/<name> and drawn by scripts/validation/report.py.
struct Series {
  std::string name;
  std::string x_label;
  std::vector<double> x;
  std::vector<std::pair<std::string, std::vector<double>>> columns;  // label, values
  bool log_log = false;                                              // drawn on log-log axes (power laws, convergence)
};

struct CaseResult {
  std::vector<Check> checks;
  std::vector<Series> series;
  std::string resolution;  // e.g. "dx = 0.02 m, h = 0.04 m, 2000 fluid particles"
  std::string details;     // free text for report.md: seeds, set-up notes
  double wall_seconds = 0.0;
};

// What every case is told about the run of `mssph validate`.
struct CaseContext {
  bool quick = false;                      // coarse, for CI on 2 cores; otherwise finer, for a GPU
  std::string physics_backend;             // the backend that runs the physics cases (resolved)
  std::string physics_backend_skip;        // non-empty: why it cannot run here (cases are SKIPPED)
  std::vector<std::string> fast_backends;  // float32 backends the kernels suite compares with reference
  std::uint64_t seed = 0;                  // fresh per run, printed; drives the random perturbations
  std::string validation_dir;              // the folder holding the cases' scenes
  std::string work_dir;                    // where cases may write run logs (inside --out)
  bool replace_logs = false;               // --force: a case's run may replace an earlier log in work_dir
};

// A case that measures on the physics backend starts with this: when that backend cannot run
// here (context.physics_backend_skip), its result is one SKIPPED check of `quantity`.
std::optional<CaseResult> skipped_without_physics_backend(const CaseContext& context, std::string quantity);

struct ValidationCase {
  std::string suite;   // "kernels", "physics", "convergence"
  std::string name;    // unique, e.g. "hydrostatic"
  std::string folder;  // relative to validation/, e.g. "physics/hydrostatic"
  std::string title;   // one line for the table and report
  std::function<CaseResult(const CaseContext&)> run;
};

// Every case, in the order they run (validation/cases.cpp).
const std::vector<ValidationCase>& all_cases();

}  // namespace mssph::validation
