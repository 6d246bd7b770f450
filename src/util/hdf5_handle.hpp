#pragma once
// RAII ownership of HDF5 C API identifiers, and checked calls: every failing HDF5 call becomes
// an exception naming what was being done.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mssph::h5 {

class Error : public std::runtime_error {
 public:
  Error(const std::string& message, int system_error) : std::runtime_error(message), system_error_(system_error) {}
  // The errno of the failed system call under HDF5 (ENOSPC: disk full), 0 when none failed.
  int system_error() const { return system_error_; }

 private:
  int system_error_ = 0;
};

// Throws h5::Error for a failed call: "HDF5: <what>", or, when HDF5's error stack records a
// failed system call, e.g. "disk full writing <file> (HDF5: <what>)".
[[noreturn]] void throw_error(const std::string& what);

// Throws h5::Error (see throw_error) when status < 0.
inline herr_t check(herr_t status, const std::string& what) {
  if (status < 0) throw_error(what);
  return status;
}

// Owns one identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer, const std::string& what) : id_(id), closer_(closer) {
    if (id_ < 0) throw_error(what);
  }
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      closer_ = other.closer_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t id() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }
  void reset() {
    if (id_ >= 0 && closer_) closer_(id_);
    id_ = H5I_INVALID_HID;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

inline Handle file(hid_t id, const std::string& what) { return Handle(id, H5Fclose, what); }
inline Handle group(hid_t id, const std::string& what) { return Handle(id, H5Gclose, what); }
inline Handle dataset(hid_t id, const std::string& what) { return Handle(id, H5Dclose, what); }
inline Handle dataspace(hid_t id, const std::string& what) { return Handle(id, H5Sclose, what); }
inline Handle datatype(hid_t id, const std::string& what) { return Handle(id, H5Tclose, what); }
inline Handle attribute(hid_t id, const std::string& what) { return Handle(id, H5Aclose, what); }
inline Handle property_list(hid_t id, const std::string& what) { return Handle(id, H5Pclose, what); }

// A new file that lives in memory only (the core driver without a backing store), named `what`
// in errors: built there, then taken whole with file_image(), so that it reaches the disk at once
// as any output does.
Handle in_memory_file(const std::string& what);
// The bytes of an open file as they would lie on disk (flushed first).
std::string file_image(hid_t file);

// Opens the group at `path`, creating it and any missing parents.
Handle open_or_create_group(hid_t file, const std::string& path);

// Whether an object exists at the absolute `path` (false, not an error, when a parent is missing).
bool object_exists(hid_t file, const std::string& path);

// The dimensions of the dataset at `path`, e.g. {rows, columns}.
std::vector<hsize_t> dataset_shape(hid_t file, const std::string& path);

// Attributes on any object (file, group, dataset); an existing attribute of the name is replaced.
void write_attribute(hid_t object, const std::string& name, const std::string& value);
void write_attribute(hid_t object, const std::string& name, double value);
void write_attribute(hid_t object, const std::string& name, long long value);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values);

std::string read_string_attribute(hid_t object, const std::string& name);
double read_double_attribute(hid_t object, const std::string& name);

// Silences HDF5's automatic error stack printing: errors surface as h5::Error instead.
void silence_error_printing();

}  // namespace mssph::h5
