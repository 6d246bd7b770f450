#include "report.hpp"

#include "util/hdf5_handle.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace mssph::validation {
namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// JSON has no NaN or infinity: a blown-up measurement is written as null.
nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json info_json(const RunInfo& info) {
  return {{"mssph_version", info.mssph_version},
          {"git_commit", info.git_commit},
          {"date", info.date},
          {"command_line", info.command_line},
          {"mode", info.mode},
          {"physics_backend", info.physics_backend},
          {"physics_device", info.physics_device},
          {"physics_precision", info.physics_precision},
          {"fast_backends", info.fast_backends},
          {"host_cpu", info.host_cpu},
          {"gpus", info.gpus},
          {"seed", info.seed}};
}

void write_info_attributes(hid_t object, const RunInfo& info) {
  h5::write_attribute(object, "mssph_version", info.mssph_version);
  h5::write_attribute(object, "git_commit", info.git_commit);
  h5::write_attribute(object, "date", info.date);
  h5::write_attribute(object, "command_line", info.command_line);
  h5::write_attribute(object, "mode", info.mode);
  h5::write_attribute(object, "physics_backend", info.physics_backend);
  h5::write_attribute(object, "physics_device", info.physics_device);
  h5::write_attribute(object, "physics_precision", info.physics_precision);
  h5::write_attribute(object, "fast_backends", join(info.fast_backends));
  h5::write_attribute(object, "host_cpu", info.host_cpu);
  h5::write_attribute(object, "gpus", join(info.gpus));
  h5::write_attribute(object, "seed", static_cast<long long>(info.seed));
}

void write_vector(hid_t group, const std::string& name, const std::vector<double>& values, const std::string& label) {
  const hsize_t size = values.size();
  h5::Handle space = h5::dataspace(H5Screate_simple(1, &size, nullptr), "dataspace for " + name);
  h5::Handle set =
      h5::dataset(H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  "create dataset " + name);
  if (size > 0)
    h5::check(H5Dwrite(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
  h5::write_attribute(set.id(), "label", label);
}

}  // namespace

Status case_status(const CaseRun& run) {
  if (!run.error.empty()) return Status::fail;
  bool all_skipped = !run.result.checks.empty();
  for (const Check& c : run.result.checks) {
    if (c.status == Status::fail) return Status::fail;
    if (c.status != Status::skipped) all_skipped = false;
  }
  if (run.result.checks.empty()) return Status::fail;  // a case that checked nothing proves nothing
  return all_skipped ? Status::skipped : Status::pass;
}

void print_table(const RunInfo& info, const std::vector<CaseRun>& runs) {
  std::printf("mssph validate (%s): physics on %s (%s, %s), kernels: %s vs reference; commit %s; %s; seed %llu\n",
              info.mode.c_str(), info.physics_backend.c_str(), info.physics_device.c_str(),
              info.physics_precision.c_str(), join(info.fast_backends).c_str(), info.git_commit.c_str(),
              info.date.c_str(), static_cast<unsigned long long>(info.seed));
  std::printf("%-11s %-22s %-40s %-9s %-14s %-12s %-10s %-9s %s\n", "suite", "case", "quantity", "backend", "expected",
              "measured", "error", "tolerance", "status");
  int counts[3] = {0, 0, 0};
  for (const CaseRun& run : runs) {
    const ValidationCase& c = *run.which;
    if (!run.error.empty()) {
      std::printf("%-11s %-22s %-40s %-9s %-14s %-12s %-10s %-9s FAIL (%s)\n", c.suite.c_str(), c.name.c_str(), "-",
                  "-", "-", "-", "-", "-", run.error.c_str());
    }
    for (const Check& k : run.result.checks) {
      std::string status = status_name(k.status);
      if (!k.note.empty()) status += " (" + k.note + ")";
      if (k.status == Status::skipped) {
        std::printf("%-11s %-22s %-40s %-9s %-14s %-12s %-10s %-9s %s\n", c.suite.c_str(), c.name.c_str(),
                    k.quantity.c_str(), k.backend.c_str(), "-", "-", "-", "-", status.c_str());
      } else {
        std::printf("%-11s %-22s %-40s %-9s %-14s %-12.5g %-10.3g %-9.3g %s\n", c.suite.c_str(), c.name.c_str(),
                    k.quantity.c_str(), k.backend.c_str(), k.expected_text.c_str(), k.measured, k.error, k.tolerance,
                    status.c_str());
      }
    }
    ++counts[static_cast<int>(case_status(run))];
  }
  std::printf("cases: %d passed, %d failed, %d skipped\n", counts[0], counts[1], counts[2]);
  std::fflush(stdout);
}

std::string report_json_text(const RunInfo& info, const std::vector<CaseRun>& runs) {
  nlohmann::json cases = nlohmann::json::array();
  for (const CaseRun& run : runs) {
    nlohmann::json checks = nlohmann::json::array();
    for (const Check& k : run.result.checks) {
      checks.push_back({{"quantity", k.quantity},
                        {"unit", k.unit},
                        {"backend", k.backend},
                        {"expected", number_or_null(k.expected)},
                        {"expected_text", k.expected_text},
                        {"measured", number_or_null(k.measured)},
                        {"error", number_or_null(k.error)},
                        {"error_kind", k.error_kind},
                        {"tolerance", k.tolerance},
                        {"status", status_name(k.status)},
                        {"note", k.note}});
    }
    nlohmann::json series = nlohmann::json::array();
    for (const Series& s : run.result.series) {
      nlohmann::json labels = nlohmann::json::array();
      for (const auto& column : s.columns) labels.push_back(column.first);
      series.push_back({{"name", s.name},
                        {"x_label", s.x_label},
                        {"columns", labels},
                        {"log_log", s.log_log},
                        {"hdf5_group", "/" + run.which->suite + "/" + run.which->name + "/" + s.name}});
    }
    cases.push_back({{"suite", run.which->suite},
                     {"case", run.which->name},
                     {"folder", "validation/" + run.which->folder},
                     {"title", run.which->title},
                     {"status", status_name(case_status(run))},
                     {"error", run.error},
                     {"resolution", run.result.resolution},
                     {"details", run.result.details},
                     {"wall_seconds", run.result.wall_seconds},
                     {"checks", checks},
                     {"series", series}});
  }
  return nlohmann::json{{"run", info_json(info)}, {"cases", cases}}.dump(2) + "\n";
}

std::string report_hdf5_image(const RunInfo& info, const std::vector<CaseRun>& runs) {
  h5::Handle file = h5::in_memory_file("validation.h5");
  write_info_attributes(file.id(), info);
  for (const CaseRun& run : runs) {
    const std::string case_path = "/" + run.which->suite + "/" + run.which->name;
    h5::Handle case_group = h5::open_or_create_group(file.id(), case_path);
    h5::write_attribute(case_group.id(), "status", std::string(status_name(case_status(run))));
    h5::write_attribute(case_group.id(), "resolution", run.result.resolution);
    for (const Series& s : run.result.series) {
      h5::Handle group = h5::open_or_create_group(file.id(), case_path + "/" + s.name);
      write_vector(group.id(), "x", s.x, s.x_label);
      for (std::size_t k = 0; k < s.columns.size(); ++k) {
        // Appended, not "y" + to_string(k): g++ 12 warns about that form (-Wrestrict, GCC bug 105651).
        std::string column_name = "y";
        column_name += std::to_string(k);
        write_vector(group.id(), column_name, s.columns[k].second, s.columns[k].first);
      }
    }
  }
  return h5::file_image(file.id());
}

}  // namespace mssph::validation
