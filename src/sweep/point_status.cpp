#include "sweep/point_status.hpp"

#include "config/strict_json.hpp"
#include "io/checkpoint_io.hpp"
#include "io/output_claim.hpp"
#include "sweep/sweep_points.hpp"
#include "util/hdf5_handle.hpp"

#include <filesystem>

namespace mssph::sweep {
namespace {

// point_hash() of the scene a log records (root attribute `config`, the scene after --set);
// "none" when it records none or one that is not JSON.
std::string scene_hash_of(hid_t file) {
  if (H5Aexists(file, "config") <= 0) return "none";
  try {
    return point_hash(parse_strict_json(h5::read_string_attribute(file, "config"), "config"));
  } catch (const InputError&) {
    return "none";
  }
}

}  // namespace

PointState classify_status(const std::string& status) {
  const auto starts = [&](const char* prefix) { return status.rfind(prefix, 0) == 0; };
  if (status == "completed") return PointState::completed;
  // `mssph run` marks a run stopped by SIGINT/SIGTERM "failed: interrupted ..." (older logs) or
  // "interrupted ..."; either way the point itself did not fail and is run again.
  if (starts("interrupted") || starts("failed: interrupted")) return PointState::interrupted;
  if (starts("failed")) return PointState::failed;
  return PointState::incomplete;
}

PointStatus read_point_status(const std::string& log_path, const std::string& point_hash) {
  // `mssph run` publishes only a completed log under its name; a run that failed, was interrupted
  // or is still going keeps it at <log>.partial.
  const std::string partial = log_path + ".partial";
  const bool published = std::filesystem::exists(log_path);
  if (!published && !std::filesystem::exists(partial)) return {PointState::missing, ""};
  if (locked_by_another_run(partial)) return {PointState::busy, "another run is writing it (it holds " + partial + ")"};
  const std::string path = published ? log_path : partial;
  h5::silence_error_printing();
  try {
    const h5::Handle file = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path);
    const std::string recorded = scene_hash_of(file.id());
    if (recorded != point_hash) {
      return {PointState::foreign, "not this point's log (" + path + " records a scene that hashes to " + recorded +
                                       ", not " + point_hash + ")"};
    }
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
    case PointState::busy:
      return "busy";
    case PointState::foreign:
      return "foreign";
  }
  return "?";
}

}  // namespace mssph::sweep
