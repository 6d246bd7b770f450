// Device recordings as HDF5: /device/t [N] (s) and /device/pose [N, 7] (x, y, z in m; qx, qy,
// qz, qw), the layout a run log's readers already know.
#include "config/recording_formats.hpp"

#include "util/errors.hpp"
#include "util/hdf5_handle.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mssph {
namespace {

constexpr const char* kTimePath = "/device/t";
constexpr const char* kPosePath = "/device/pose";

// Whether `path` (absolute, one group deep) exists: H5Lexists fails rather than answering false
// when the parent group is missing, so the parent is looked up first.
bool exists(hid_t file, const std::string& parent, const std::string& path) {
  if (h5::check(H5Lexists(file, parent.c_str(), H5P_DEFAULT), "look up " + parent) <= 0) return false;
  return h5::check(H5Lexists(file, path.c_str(), H5P_DEFAULT), "look up " + path) > 0;
}

std::vector<hsize_t> shape_of(hid_t set, const std::string& what) {
  h5::Handle space = h5::dataspace(H5Dget_space(set), "space of " + what);
  const int rank = h5::check(H5Sget_simple_extent_ndims(space.id()), "rank of " + what);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  h5::check(H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr), "dimensions of " + what);
  return dims;
}

std::string describe_shape(const std::vector<hsize_t>& dims) {
  std::string text = "[";
  for (std::size_t i = 0; i < dims.size(); ++i) text += (i ? ", " : "") + std::to_string(dims[i]);
  return text + "]";
}

std::vector<double> read_doubles(hid_t set, std::size_t count, const std::string& path, const std::string& name) {
  h5::Handle type = h5::datatype(H5Dget_type(set), "type of " + name);
  if (H5Tget_class(type.id()) != H5T_FLOAT && H5Tget_class(type.id()) != H5T_INTEGER) {
    throw InputError(path + ": " + name + ": expected numbers");
  }
  std::vector<double> values(count);
  h5::check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + name);
  return values;
}

void write_dataset(hid_t file, const char* name, const std::vector<double>& values, const std::vector<hsize_t>& dims,
                   const std::string& units, const std::string& description) {
  h5::Handle space = h5::dataspace(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                                   std::string("space of ") + name);
  h5::Handle set =
      h5::dataset(H5Dcreate2(file, name, H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  std::string("create ") + name);
  h5::check(H5Dwrite(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
            std::string("write ") + name);
  h5::write_attribute(set.id(), "units", units);
  h5::write_attribute(set.id(), "description", description);
}

// The layout above, read from an open file; a failing HDF5 call throws h5::Error.
RawRecording read_layout(const std::string& path) {
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) throw InputError(path + ": cannot open as an HDF5 device recording");
  h5::Handle file = h5::file(id, "open " + path);
  for (const char* name : {kTimePath, kPosePath}) {
    if (!exists(file.id(), "/device", name)) {
      throw InputError(path + ": missing dataset " + name +
                       " (expected /device/t [N] in s and /device/pose [N, 7]: x, y, z, qx, qy, qz, qw)");
    }
  }
  h5::Handle time_set = h5::dataset(H5Dopen2(file.id(), kTimePath, H5P_DEFAULT), std::string("open ") + kTimePath);
  h5::Handle pose_set = h5::dataset(H5Dopen2(file.id(), kPosePath, H5P_DEFAULT), std::string("open ") + kPosePath);
  const std::vector<hsize_t> time_shape = shape_of(time_set.id(), kTimePath);
  const std::vector<hsize_t> pose_shape = shape_of(pose_set.id(), kPosePath);
  if (time_shape.size() != 1) {
    throw InputError(path + ": " + kTimePath + ": expected a 1-D dataset [N], got shape " + describe_shape(time_shape));
  }
  if (pose_shape.size() != 2 || pose_shape[1] != 7 || pose_shape[0] != time_shape[0]) {
    throw InputError(path + ": " + kPosePath + ": expected shape [" + std::to_string(time_shape[0]) +
                     ", 7] (one x, y, z, qx, qy, qz, qw row per time in " + kTimePath + "), got " +
                     describe_shape(pose_shape));
  }
  if (time_shape[0] > kMaxRecordingSamples) {
    throw InputError(path + ": " + kTimePath + ": " + std::to_string(time_shape[0]) + " samples, more than the " +
                     std::to_string(kMaxRecordingSamples) + " a device recording may hold");
  }
  const std::size_t n = time_shape[0];
  RawRecording out;
  out.row_word = "/device row";
  out.time = read_doubles(time_set.id(), n, path, kTimePath);
  const std::vector<double> flat = read_doubles(pose_set.id(), 7 * n, path, kPosePath);
  out.pose.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 7; ++k) out.pose[i][k] = flat[7 * i + k];
    out.row_number.push_back(i);
  }
  return out;
}

// What the reading process sends back: a tag, then the recording or the error's message.
enum class Reply : char { recording = 'r', input_error = 'i', hdf5_error = 'h', other_error = 'x' };

std::string encode(const RawRecording& recording) {
  const std::uint64_t n = recording.time.size();
  std::string bytes(1, static_cast<char>(Reply::recording));
  bytes.append(reinterpret_cast<const char*>(&n), sizeof n);
  bytes.append(reinterpret_cast<const char*>(recording.time.data()), n * sizeof(double));
  bytes.append(reinterpret_cast<const char*>(recording.pose.data()), n * sizeof(recording.pose[0]));
  return bytes;
}

RawRecording decode(const std::string& bytes) {
  std::uint64_t n = 0;
  if (bytes.size() < 1 + sizeof n) throw std::runtime_error("reading an HDF5 recording: short reply");
  std::memcpy(&n, bytes.data() + 1, sizeof n);
  RawRecording out;
  if (n > kMaxRecordingSamples || bytes.size() != 1 + sizeof n + n * (sizeof(double) + sizeof(out.pose[0]))) {
    throw std::runtime_error("reading an HDF5 recording: malformed reply");
  }
  out.row_word = "/device row";
  out.time.resize(n);
  out.pose.resize(n);
  std::memcpy(out.time.data(), bytes.data() + 1 + sizeof n, n * sizeof(double));
  std::memcpy(out.pose.data(), bytes.data() + 1 + sizeof n + n * sizeof(double), n * sizeof(out.pose[0]));
  for (std::size_t i = 0; i < n; ++i) out.row_number.push_back(i);
  return out;
}

// In the child process: reads the file, sends the outcome down `fd` and exits.
[[noreturn]] void read_in_child(const std::string& path, int fd) {
  // A crash in libhdf5 should end this process by its signal, without handlers of the parent's
  // (a sanitizer's or libFuzzer's) reporting it as the parent's crash.
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
  std::string reply;
  try {
    reply = encode(read_layout(path));
  } catch (const InputError& e) {
    reply = static_cast<char>(Reply::input_error) + std::string(e.what());
  } catch (const h5::Error& e) {
    reply = static_cast<char>(Reply::hdf5_error) + std::string(e.what());
  } catch (const std::exception& e) {
    reply = static_cast<char>(Reply::other_error) + std::string(e.what());
  }
  for (std::size_t sent = 0; sent < reply.size();) {
    const ssize_t n = write(fd, reply.data() + sent, reply.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(1);
    sent += static_cast<std::size_t>(n);
  }
  _exit(0);  // no atexit handlers, no flushing of the parent's buffered output
}

}  // namespace

// libhdf5 (1.10.8, Debian 12) can crash on a damaged file: one the trajectory fuzzer found makes
// H5Lexists read through a null pointer, and h5dump and h5py crash on it too. A bad input must
// end in a message and exit code 2, so the file is read in a child process; its crash is
// reported as a damaged file.
RawRecording read_hdf5_recording(const std::string& path) {
  h5::silence_error_printing();
  // Looking for the signature reads no structure: a file without one needs no process.
  if (H5Fis_hdf5(path.c_str()) <= 0) throw InputError(path + ": cannot open as an HDF5 device recording");
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("reading " + path + ": pipe: " + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error("reading " + path + ": fork: " + std::strerror(errno));
  }
  if (pid == 0) {
    close(fds[0]);
    read_in_child(path, fds[1]);
  }
  close(fds[1]);
  std::string reply;
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    throw InputError(path + ": cannot read the HDF5 device recording, damaged: the HDF5 library crashed on it (" +
                     strsignal(WTERMSIG(status)) + ")");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty()) {
    throw std::runtime_error("reading " + path + ": the reading process failed (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  const auto tag = static_cast<Reply>(reply[0]);
  if (tag == Reply::recording) return decode(reply);  // decoded from the reply itself, not a copy
  const std::string message = reply.substr(1);
  if (tag == Reply::input_error) throw InputError(message);
  if (tag == Reply::hdf5_error) {
    // HDF5 opened the file but could not follow its structure (a cut or overwritten file), or
    // the system failed to read it: either way the input is unusable, not mssph at fault.
    throw InputError(path + ": cannot read the HDF5 device recording, damaged or unreadable (" + message + ")");
  }
  throw std::runtime_error(message);
}

std::string hdf5_recording_image(const RawRecording& recording) {
  h5::silence_error_printing();
  h5::Handle file = h5::in_memory_file("device recording");
  h5::open_or_create_group(file.id(), "/device");
  const hsize_t n = recording.time.size();
  std::vector<double> flat;
  flat.reserve(7 * n);
  for (const auto& row : recording.pose) flat.insert(flat.end(), row.begin(), row.end());
  write_dataset(file.id(), kTimePath, recording.time, {n}, "s", "time of each device sample");
  write_dataset(file.id(), kPosePath, flat, {n, 7}, "m, m, m, 1, 1, 1, 1",
                "handle pose in the device frame: position and unit quaternion (scalar last)");
  {
    std::vector<std::string> columns(kRecordingColumns.begin() + 1, kRecordingColumns.end());
    h5::Handle pose = h5::dataset(H5Dopen2(file.id(), kPosePath, H5P_DEFAULT), std::string("open ") + kPosePath);
    h5::write_attribute(pose.id(), "columns", columns);
  }
  return h5::file_image(file.id());
}

}  // namespace mssph
