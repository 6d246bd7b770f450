#pragma once
// The two file formats of device recordings (see device_recording.hpp), without validation
// beyond the format itself: device_recording.cpp checks the values and names the row.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace mssph {

struct RawRecording {
  std::vector<double> time;                 // [s]
  std::vector<std::array<double, 7>> pose;  // x, y, z, qx, qy, qz, qw
  // How an error names sample i: "<row_word> <row_number[i]>", e.g. "line 7" in a CSV file
  // (the line an editor shows) or "/device row 6" in an HDF5 file (the index h5py shows).
  std::string row_word;
  std::vector<std::size_t> row_number;

  std::string row_name(std::size_t i) const { return row_word + " " + std::to_string(row_number[i]); }
};

// The most samples a recording may hold: almost 3 hours of a 1 kHz device, 0.6 GB in memory
// (twice that while an HDF5 file is read).
// A file claiming more (an HDF5 dataset's shape is only a header field) is refused before
// anything is allocated for it.
inline constexpr std::size_t kMaxRecordingSamples = 10'000'000;

// The CSV columns, in the order the writer uses.
inline const std::array<const char*, 8> kRecordingColumns = {"t", "x", "y", "z", "qx", "qy", "qz", "qw"};

RawRecording read_csv_recording(const std::string& path);
// The text of a CSV recording: the header, then one line per sample.
std::string csv_recording_text(const RawRecording& recording);

RawRecording read_hdf5_recording(const std::string& path);
// The bytes of an HDF5 recording, built in memory (h5::in_memory_file).
std::string hdf5_recording_image(const RawRecording& recording);

}  // namespace mssph
