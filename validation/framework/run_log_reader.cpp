#include "framework/run_log_reader.hpp"

#include "util/hdf5_handle.hpp"

#include <stdexcept>

namespace mssph::validation {
namespace {

std::vector<double> read_all(const std::string& file, const std::string& dataset, std::size_t columns) {
  h5::Handle f = h5::file(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + file);
  const std::vector<hsize_t> shape = h5::dataset_shape(f.id(), dataset);
  const std::size_t expected_rank = columns == 1 ? 1 : 2;
  if (shape.size() != expected_rank || (columns > 1 && shape[1] != columns)) {
    throw std::runtime_error(file + ": " + dataset + " does not have " + std::to_string(columns) + " column(s)");
  }
  h5::Handle set = h5::dataset(H5Dopen2(f.id(), dataset.c_str(), H5P_DEFAULT), "open " + dataset + " in " + file);
  std::vector<double> values(shape[0] * columns);
  if (!values.empty()) {
    h5::check(H5Dread(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + dataset);
  }
  return values;
}

}  // namespace

std::vector<Eigen::Vector3d> read_vectors(const std::string& file, const std::string& dataset) {
  const std::vector<double> flat = read_all(file, dataset, 3);
  std::vector<Eigen::Vector3d> vectors;
  for (std::size_t k = 0; k + 2 < flat.size(); k += 3) vectors.emplace_back(flat[k], flat[k + 1], flat[k + 2]);
  return vectors;
}

std::vector<double> read_series(const std::string& file, const std::string& dataset) {
  return read_all(file, dataset, 1);
}

}  // namespace mssph::validation
