#include "config/device_recording.hpp"

#include "config/recording_formats.hpp"
#include "util/errors.hpp"
#include "util/file_kind.hpp"

#include <sys/stat.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace mssph {
namespace {

enum class Format { csv, hdf5 };

Format format_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".csv") return Format::csv;
  if (extension == ".h5" || extension == ".hdf5") return Format::hdf5;
  throw InputError(path + ": unknown device recording format \"" + extension +
                   "\": expected a .csv file (header t,x,y,z,qx,qy,qz,qw) or an .h5/.hdf5 file (/device/t, "
                   "/device/pose)");
}

// The shortest decimal form that reads back as x: what the file most likely says.
std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

// Checks one sample and returns its pose with the quaternion normalised.
Pose checked_pose(const RawRecording& raw, std::size_t i, const std::string& path, const RecordingLimits& limits) {
  const auto fail = [&](const std::string& message) {
    throw InputError(path + ": " + raw.row_name(i) + ": " + message);
  };
  const auto& p = raw.pose[i];
  if (!std::isfinite(raw.time[i])) fail("t is not a finite number");
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!std::isfinite(p[k])) fail(std::string("column ") + kRecordingColumns[k + 1] + " is not a finite number");
  }
  if (i > 0 && !(raw.time[i] > raw.time[i - 1])) {
    fail("t = " + number(raw.time[i]) + " s is not after the previous sample's t = " + number(raw.time[i - 1]) +
         " s (times must increase strictly: " + (raw.time[i] == raw.time[i - 1] ? "duplicate time)" : "out of order)"));
  }
  const Eigen::Quaterniond q(p[6], p[3], p[4], p[5]);
  if (std::abs(q.norm() - 1.0) > kQuaternionNormTolerance) {
    fail("quaternion (qx, qy, qz, qw) has norm " + number(q.norm()) + ", expected a unit quaternion (within " +
         number(kQuaternionNormTolerance) + ")");
  }
  const Eigen::Vector3d x(p[0], p[1], p[2]);
  if (x.norm() > limits.workspace_radius) {
    fail("position (" + number(x.x()) + ", " + number(x.y()) + ", " + number(x.z()) + ") m is " + number(x.norm()) +
         " m from the device origin, outside the workspace radius " + number(limits.workspace_radius) + " m");
  }
  return Pose{x, q.normalized()};
}

}  // namespace

void check_recording_path(const std::string& path) { format_of(path); }

DeviceRecording read_device_recording(const std::string& path, const RecordingLimits& limits) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw InputError(path + ": no such device recording file");
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path + ": is " + file_kind(st) + ", not a device recording file (a regular .csv or .h5 file)");
  }
  const RawRecording raw = format_of(path) == Format::csv ? read_csv_recording(path) : read_hdf5_recording(path);
  if (raw.time.empty()) throw InputError(path + ": the device recording holds no sample");
  DeviceRecording out;
  out.time = raw.time;
  out.pose.reserve(raw.pose.size());
  for (std::size_t i = 0; i < raw.pose.size(); ++i) out.pose.push_back(checked_pose(raw, i, path, limits));
  return out;
}

std::string device_recording_bytes(const std::string& path, const DeviceRecording& recording) {
  RawRecording raw;
  raw.time = recording.time;
  for (const Pose& p : recording.pose) {
    const Eigen::Quaterniond& q = p.orientation;
    raw.pose.push_back({p.position.x(), p.position.y(), p.position.z(), q.x(), q.y(), q.z(), q.w()});
  }
  return format_of(path) == Format::csv ? csv_recording_text(raw) : hdf5_recording_image(raw);
}

}  // namespace mssph
