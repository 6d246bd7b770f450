// Writes valid device recordings, one per format, into the folder given as argument: seeds for
// the trajectory fuzzer besides the malformed corpus (tests/corpus/trajectories). They come from
// mssph's own writer (what `--record-device` writes) rather than from files in the repository,
// so the HDF5 seed always has the layout this build reads.
#include "config/device_recording.hpp"

#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " FOLDER\n";
    return 2;
  }
  // A slow circle in the device's workspace, turning about z: a few samples of a plausible hand.
  mssph::DeviceRecording recording;
  for (int i = 0; i < 5; ++i) {
    const double t = 0.001 * i;
    const double angle = 0.5 * std::numbers::pi * i / 4.0;
    recording.time.push_back(t);
    recording.pose.push_back(mssph::Pose{Eigen::Vector3d(0.1 * std::cos(angle), 0.1 * std::sin(angle), 0.05),
                                         Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()))});
  }
  try {
    for (const char* name : {"valid.csv", "valid.h5"}) {
      const std::string path = std::string(argv[1]) + "/" + name;
      std::ofstream file(path, std::ios::binary);
      file << mssph::device_recording_bytes(path, recording);
      if (!file.flush()) throw std::runtime_error(path + ": cannot write");
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
