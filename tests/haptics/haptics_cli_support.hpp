#pragma once
// Running the mssph binary on haptic scenes and reading their /haptics group back with the HDF5
// C API (tests/io's readers), for the command-line and scene tests.
#include "child_process.hpp"
#include "h5_read.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mssph::test {

// `mssph run ARGS --backend reference` (the oracle backend, whatever "auto" picks) in `cwd`.
inline ProcessResult run_mssph(std::vector<std::string> args, const std::filesystem::path& cwd) {
  args.insert(args.begin(), MSSPH_BINARY);
  args.insert(args.end(), {"--backend", "reference"});
  // Scene runs on a loaded 2-core machine take minutes, not the default minute.
  return ChildProcess(args, cwd, cwd).wait(std::chrono::minutes(10));
}

// A run log's rows of an N x 3 dataset.
inline std::vector<Eigen::Vector3d> read_vec3(hid_t file, const std::string& path) {
  const std::vector<double> flat = read_doubles(file, path);
  std::vector<Eigen::Vector3d> rows;
  for (std::size_t i = 0; i + 2 < flat.size(); i += 3) rows.emplace_back(flat[i], flat[i + 1], flat[i + 2]);
  return rows;
}

inline double haptics_attribute(hid_t file, const std::string& name) {
  return h5::read_double_attribute(open_object(file, "/haptics").id(), name);
}

}  // namespace mssph::test
