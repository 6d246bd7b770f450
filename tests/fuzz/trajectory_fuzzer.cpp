// libFuzzer target: any bytes as a recorded device trajectory (device_recording.hpp), read once
// as a CSV file and once as an HDF5 file. The readers take a path, so the bytes are written to a
// file of each extension first. Bad input must end in InputError (what `mssph run` reports with
// exit code 2); any other exception, crash, leak or undefined behaviour (with the sanitizers this
// target is built with) is a bug. HDF5 itself is the system's uninstrumented library, run in a
// child process (recording_hdf5.cpp): a crash inside it is a refused input, its memory errors
// go unseen, and libFuzzer sees no coverage in it.
#include "config/device_recording.hpp"
#include "config/haptics_config.hpp"
#include "util/errors.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

// In memory where the system lets us write to its tmpfs at /dev/shm: rewriting a file on disk
// for every input made the target ten times slower (150 inputs per second instead of 1,600).
std::filesystem::path scratch_root() {
  if (access("/dev/shm", W_OK | X_OK) == 0) return "/dev/shm";
  return std::filesystem::temp_directory_path();
}

// One folder per process (libFuzzer's -jobs and -fork run several), removed at exit.
class ScratchFolder {
 public:
  ScratchFolder() : path_(scratch_root() / ("mssph-trajectory-fuzz-" + std::to_string(getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  std::string file(const char* name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

void read_as(const std::string& path, const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  // The limit a scene gets unless it sets proxy/device/workspace_radius.
  const mssph::RecordingLimits limits{mssph::DeviceConfig{}.workspace_radius};
  try {
    mssph::read_device_recording(path, limits);
  } catch (const mssph::InputError&) {
    // The expected outcome for almost every input.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ScratchFolder scratch;
  read_as(scratch.file("recording.csv"), data, size);
  read_as(scratch.file("recording.h5"), data, size);
  return 0;
}
