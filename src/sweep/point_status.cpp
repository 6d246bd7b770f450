#include "sweep/point_status.hpp"

#include "io/checkpoint_io.hpp"
#include "util/hdf5_handle.hpp"

#include <filesystem>

namespace mssph::sweep {

PointState classify_status(const std::string& status) {
  const auto starts = [&](const char* prefix) { return status.rfind(prefix, 0) == 0; };
  if (status == "completed") return PointState::completed;
  // `mssph run` marks a run stopped by SIGINT/SIGTERM "failed: interrupted ..." (older logs) or
  // "interrupted ..."; either way the point itself did not fail and is run again.
  if (starts("interrupted") || starts("failed: interrupted")) return PointState::interrupted;
  if (starts("failed")) return PointState::failed;
  return PointState::incomplete;
}

PointStatus read_point_status(const std::string& log_path) {
  // `mssph run` publishes only a completed log under its name; a run that failed, was interrupted
  // or is still going keeps it at <log>.partial.
  const std::string partial = log_path + ".partial";
  const bool published = std::filesystem::exists(log_path);
  if (!published && !std::filesystem::exists(partial)) return {PointState::missing, ""};
  const std::string path = published ? log_path : partial;
  h5::silence_error_printing();
  try {
    const h5::Handle file = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path);
    const std::string status = h5::read_string_attribute(file.id(), "status");
    const PointState state = classify_status(status);
    const bool unfinished = state == PointState::interrupted || state == PointState::incomplete;
    return {state, status, !published && unfinished && latest_checkpoint_step(file.id()) >= 0};
  } catch (const h5::Error& e) {
    return {PointState::incomplete, std::string("unreadable (") + e.what() + ")"};
  }
}

const char* to_string(PointState state) {
  switch (state) {
    case PointState::missing:
      return "missing";
    case PointState::completed:
      return "completed";
    case PointState::failed:
      return "failed";
    case PointState::interrupted:
      return "interrupted";
    case PointState::incomplete:
      return "incomplete";
  }
  return "?";
}

}  // namespace mssph::sweep
