#pragma once
// Device trajectories on disk: the handle's pose over time, in the device frame, as a real
// Virtuose reports it. Two formats, chosen by the file name's extension:
//   .csv          header t,x,y,z,qx,qy,qz,qw (any column order), one row per sample;
//   .h5 / .hdf5   datasets /device/t [N] (s) and /device/pose [N, 7] (x, y, z, qx, qy, qz, qw).
// Reading validates every row and names the file and the row of the first problem (InputError).
// Writing uses the same formats, so a run's own trajectory can be replayed (`--record-device`):
// this layer makes the file's bytes, which the run writes as any output (io/output_file.hpp).
#include "util/pose.hpp"

#include <string>
#include <vector>

namespace mssph {

struct DeviceRecording {
  std::vector<double> time;  // [s], strictly increasing
  std::vector<Pose> pose;    // device frame
};

// What a valid recording satisfies besides its format.
struct RecordingLimits {
  double workspace_radius = 0.0;  // every position within this distance of the device origin [m]
};

// Unit quaternions in a file may be rounded (a driver writing 4 decimals is off by up to 2e-4
// in norm); beyond this the row is malformed (a zero or mistyped quaternion), not rounded.
inline constexpr double kQuaternionNormTolerance = 1e-3;

// Throws InputError naming `path` when there is no such file or it is not a regular file (a FIFO
// is never opened: reading one would wait for a writer).
DeviceRecording read_device_recording(const std::string& path, const RecordingLimits& limits);
// The bytes of the file `path` holding `recording`, in the format its extension names.
std::string device_recording_bytes(const std::string& path, const DeviceRecording& recording);

// Throws InputError unless `path` names a format above (by extension).
void check_recording_path(const std::string& path);

}  // namespace mssph
