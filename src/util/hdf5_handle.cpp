#include "util/hdf5_handle.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace mssph::h5 {
namespace {

Handle variable_string_type() {
  Handle type = datatype(H5Tcopy(H5T_C_S1), "copy string type");
  check(H5Tset_size(type.id(), H5T_VARIABLE), "set variable string size");
  check(H5Tset_cset(type.id(), H5T_CSET_UTF8), "set UTF-8");
  return type;
}

void remove_if_present(hid_t object, const std::string& name) {
  if (check(H5Aexists(object, name.c_str()), "look up attribute " + name) > 0) {
    check(H5Adelete(object, name.c_str()), "replace attribute " + name);
  }
}

// What HDF5's error stack says about a failed system call: its file drivers record
// "..., filename = '<name>', ..., errno = <n>, error message = '<text>'" (H5FDsec2.c).
struct SystemFailure {
  int error = 0;
  std::string file;
};

herr_t find_system_failure(unsigned, const H5E_error2_t* entry, void* data) {
  auto* failure = static_cast<SystemFailure*>(data);
  if (failure->error != 0 || entry->desc == nullptr) return 0;
  const std::string desc = entry->desc;
  const auto at = desc.find("errno = ");
  if (at == std::string::npos) return 0;
  failure->error = std::atoi(desc.c_str() + at + 8);
  const auto name = desc.find("filename = '");
  if (name != std::string::npos) {
    const auto start = name + 12;
    failure->file = desc.substr(start, desc.find('\'', start) - start);
  }
  return 0;
}

}  // namespace

void throw_error(const std::string& what) {
  SystemFailure failure;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, find_system_failure, &failure);
  if (failure.error == 0) throw Error("HDF5: " + what, 0);
  const std::string file = failure.file.empty() ? std::string("the file") : failure.file;
  const std::string cause = failure.error == ENOSPC  ? "disk full writing " + file
                            : failure.error == EFBIG ? "file size limit (ulimit -f) reached writing " + file
                                                     : std::string(std::strerror(failure.error)) + " on " + file;
  throw Error(cause + " (HDF5: " + what + ")", failure.error);
}

Handle in_memory_file(const std::string& what) {
  Handle access = property_list(H5Pcreate(H5P_FILE_ACCESS), "file access properties");
  check(H5Pset_fapl_core(access.id(), 1 << 16, false), "keep " + what + " in memory");
  return file(H5Fcreate(what.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id()), "create " + what + " in memory");
}

std::string file_image(hid_t file) {
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush a file in memory");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size < 0) throw_error("size of a file in memory");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(file, bytes.data(), bytes.size()) < 0) throw_error("copy a file in memory");
  return bytes;
}

Handle open_or_create_group(hid_t file, const std::string& path) {
  std::string partial;
  std::istringstream parts(path);
  Handle current = group(H5Gopen2(file, "/", H5P_DEFAULT), "open root group");
  for (std::string part; std::getline(parts, part, '/');) {
    if (part.empty()) continue;
    partial += "/" + part;
    const htri_t exists = H5Lexists(file, partial.c_str(), H5P_DEFAULT);
    current = exists > 0 ? group(H5Gopen2(file, partial.c_str(), H5P_DEFAULT), "open group " + partial)
                         : group(H5Gcreate2(file, partial.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                 "create group " + partial);
  }
  return current;
}

bool object_exists(hid_t file, const std::string& path) {
  // H5Lexists fails (rather than answering false) when an intermediate group is missing, so
  // every prefix is looked up in turn.
  std::string partial;
  std::istringstream parts(path);
  for (std::string part; std::getline(parts, part, '/');) {
    if (part.empty()) continue;
    partial += "/" + part;
    if (check(H5Lexists(file, partial.c_str(), H5P_DEFAULT), "look up " + partial) == 0) return false;
  }
  return true;
}

std::vector<hsize_t> dataset_shape(hid_t file, const std::string& path) {
  Handle set = dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open " + path);
  Handle space = dataspace(H5Dget_space(set.id()), "space of " + path);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  check(rank, "rank of " + path);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr), "dimensions of " + path);
  return dims;
}

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  remove_if_present(object, name);
  Handle type = variable_string_type();
  Handle space = dataspace(H5Screate(H5S_SCALAR), "scalar space");
  Handle attr = attribute(H5Acreate2(object, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                          "create attribute " + name);
  const char* data = value.c_str();
  check(H5Awrite(attr.id(), type.id(), &data), "write attribute " + name);
}

void write_attribute(hid_t object, const std::string& name, double value) {
  remove_if_present(object, name);
  Handle space = dataspace(H5Screate(H5S_SCALAR), "scalar space");
  Handle attr = attribute(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                          "create attribute " + name);
  check(H5Awrite(attr.id(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void write_attribute(hid_t object, const std::string& name, long long value) {
  remove_if_present(object, name);
  Handle space = dataspace(H5Screate(H5S_SCALAR), "scalar space");
  Handle attr = attribute(H5Acreate2(object, name.c_str(), H5T_STD_I64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                          "create attribute " + name);
  check(H5Awrite(attr.id(), H5T_NATIVE_LLONG, &value), "write attribute " + name);
}

void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values) {
  remove_if_present(object, name);
  Handle type = variable_string_type();
  const hsize_t count = values.size();
  // An empty list is an attribute with a null dataspace (h5py reads it as h5py.Empty).
  Handle space = values.empty() ? dataspace(H5Screate(H5S_NULL), "empty space")
                                : dataspace(H5Screate_simple(1, &count, nullptr), "string list space");
  Handle attr = attribute(H5Acreate2(object, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                          "create attribute " + name);
  if (values.empty()) return;
  std::vector<const char*> data;
  for (const std::string& v : values) data.push_back(v.c_str());
  check(H5Awrite(attr.id(), type.id(), data.data()), "write attribute " + name);
}

std::string read_string_attribute(hid_t object, const std::string& name) {
  Handle attr = attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name);
  Handle type = variable_string_type();
  char* data = nullptr;
  check(H5Aread(attr.id(), type.id(), &data), "read attribute " + name);
  std::string value = data ? data : "";
  H5free_memory(data);
  return value;
}

double read_double_attribute(hid_t object, const std::string& name) {
  Handle attr = attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name);
  double value = 0.0;
  check(H5Aread(attr.id(), H5T_NATIVE_DOUBLE, &value), "read attribute " + name);
  return value;
}

void silence_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

}  // namespace mssph::h5
