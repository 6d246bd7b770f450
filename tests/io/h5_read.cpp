#include "h5_read.hpp"

namespace mssph::test {
namespace {

template <typename T>
std::vector<T> read_all(hid_t file, const std::string& path, hid_t memory_type) {
  h5::Handle set = h5::dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open " + path);
  h5::Handle space = h5::dataspace(H5Dget_space(set.id()), "space of " + path);
  const hssize_t count = H5Sget_simple_extent_npoints(space.id());
  if (count < 0) h5::throw_error("size of " + path);
  std::vector<T> values(static_cast<std::size_t>(count));
  if (count > 0)
    h5::check(H5Dread(set.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + path);
  return values;
}

}  // namespace

h5::Handle open_read_only(const std::string& path) {
  h5::silence_error_printing();
  // A live log's partial file is locked by its writer (flock): read it as the README says,
  // without HDF5's own file locking.
  h5::Handle access = h5::property_list(H5Pcreate(H5P_FILE_ACCESS), "file access properties");
  h5::check(H5Pset_file_locking(access.id(), false, true), "turn off file locking");
  return h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.id()), "open " + path);
}

h5::Handle open_object(hid_t file, const std::string& path) {
  return h5::Handle(H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose, "open " + path);
}

long long read_integer_attribute(hid_t object, const std::string& name) {
  h5::Handle attr = h5::attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name);
  long long value = 0;
  h5::check(H5Aread(attr.id(), H5T_NATIVE_LLONG, &value), "read attribute " + name);
  return value;
}

std::vector<std::string> read_string_list_attribute(hid_t object, const std::string& name) {
  h5::Handle attr = h5::attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name);
  h5::Handle space = h5::dataspace(H5Aget_space(attr.id()), "space of attribute " + name);
  if (H5Sget_simple_extent_type(space.id()) == H5S_NULL) return {};
  const hssize_t count = H5Sget_simple_extent_npoints(space.id());
  if (count < 0) h5::throw_error("size of attribute " + name);
  h5::Handle type = h5::datatype(H5Aget_type(attr.id()), "type of attribute " + name);
  std::vector<char*> data(static_cast<std::size_t>(count));
  h5::check(H5Aread(attr.id(), type.id(), data.data()), "read attribute " + name);
  std::vector<std::string> values(data.begin(), data.end());
  h5::check(H5Dvlen_reclaim(type.id(), space.id(), H5P_DEFAULT, data.data()), "free attribute " + name);
  return values;
}

bool has_attribute(hid_t object, const std::string& name) {
  return h5::check(H5Aexists(object, name.c_str()), "look up attribute " + name) > 0;
}

std::vector<double> read_doubles(hid_t file, const std::string& path) {
  return read_all<double>(file, path, H5T_NATIVE_DOUBLE);
}
std::vector<float> read_floats(hid_t file, const std::string& path) {
  return read_all<float>(file, path, H5T_NATIVE_FLOAT);
}
std::vector<int> read_ints(hid_t file, const std::string& path) { return read_all<int>(file, path, H5T_NATIVE_INT); }

std::vector<hsize_t> max_shape(hid_t file, const std::string& path) {
  h5::Handle set = h5::dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open " + path);
  h5::Handle space = h5::dataspace(H5Dget_space(set.id()), "space of " + path);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.id())));
  std::vector<hsize_t> maximum(dims.size());
  h5::check(H5Sget_simple_extent_dims(space.id(), dims.data(), maximum.data()), "dimensions of " + path);
  return maximum;
}

bool is_chunked(hid_t file, const std::string& path) {
  h5::Handle set = h5::dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open " + path);
  h5::Handle properties = h5::property_list(H5Dget_create_plist(set.id()), "properties of " + path);
  return H5Pget_layout(properties.id()) == H5D_CHUNKED;
}

}  // namespace mssph::test
