#pragma once
// The outputs of `mssph validate`: the table on stdout, report.json, and validation.h5 with the
// raw series. report.md and its plots are drawn from these two files by
// scripts/validation/report.py.
#include "framework/validation_case.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// Where and how the validation ran, recorded in every output.
struct RunInfo {
  std::string mssph_version;
  std::string git_commit;
  std::string date;  // UTC, ISO 8601
  std::string command_line;
  std::string mode;  // "quick" or "full"
  std::string physics_backend;
  std::string physics_device;
  std::string physics_precision;
  std::vector<std::string> fast_backends;
  std::string host_cpu;
  std::vector<std::string> gpus;
  std::uint64_t seed = 0;
};

struct CaseRun {
  const ValidationCase* which = nullptr;
  CaseResult result;
  std::string error;  // the case threw: it failed with this message
};

// The overall status of a case: FAIL if any check failed or the case threw, SKIPPED if every
// check was skipped, else PASS.
Status case_status(const CaseRun& run);

void print_table(const RunInfo& info, const std::vector<CaseRun>& runs);
// The contents of report.json and of validation.h5 (built in memory), which `mssph validate`
// writes as it writes every output (io/output_file.hpp).
std::string report_json_text(const RunInfo& info, const std::vector<CaseRun>& runs);
std::string report_hdf5_image(const RunInfo& info, const std::vector<CaseRun>& runs);

}  // namespace mssph::validation
