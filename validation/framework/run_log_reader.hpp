#pragma once
// Reading series back from a run log (the HDF5 file `mssph run` writes), for cases measured from
// a run's log.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace mssph::validation {

// A dataset of shape [N, 3] (e.g. /haptics/interaction/force) as N vectors.
std::vector<Eigen::Vector3d> read_vectors(const std::string& file, const std::string& dataset);

// A dataset of shape [N] (e.g. /haptics/time).
std::vector<double> read_series(const std::string& file, const std::string& dataset);

}  // namespace mssph::validation
