#pragma once
// Reading run logs back with the HDF5 C API, independently of the writer's code paths: whole
// datasets, their shapes and layouts, and attributes of every type the run log writes.
#include "util/hdf5_handle.hpp"

#include <string>
#include <vector>

namespace mssph::test {

h5::Handle open_read_only(const std::string& path);
h5::Handle open_object(hid_t file, const std::string& path);  // a group or a dataset

long long read_integer_attribute(hid_t object, const std::string& name);
std::vector<std::string> read_string_list_attribute(hid_t object, const std::string& name);
bool has_attribute(hid_t object, const std::string& name);

// A whole dataset in row-major order, converted by HDF5 to the requested type.
std::vector<double> read_doubles(hid_t file, const std::string& path);
std::vector<float> read_floats(hid_t file, const std::string& path);
std::vector<int> read_ints(hid_t file, const std::string& path);

// The dataset's maximum dimensions (H5S_UNLIMITED where extensible) and whether it is chunked.
std::vector<hsize_t> max_shape(hid_t file, const std::string& path);
bool is_chunked(hid_t file, const std::string& path);

}  // namespace mssph::test
