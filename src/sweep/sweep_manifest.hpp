#pragma once
// DIR/sweep.json: what a sweep's output folder holds, written before any point runs. It lists
// every point (index, hash, log file, parameter values, seed, overrides) so that `mssph sweep
// merge DIR` (scripts/sweep/summarize.py) and `mssph sweep plot DIR` need nothing but the folder,
// and a point's log can be matched to its parameters without reading it.
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_points.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mssph::sweep {

inline constexpr const char* kManifestName = "sweep.json";
inline constexpr const char* kPointsFolder = "points";

struct ManifestContext {
  std::vector<std::string> command_line_overrides;
  std::string backend;
};

nlohmann::json make_manifest(const SweepFile& sweep, const std::vector<SweepPoint>& points,
                             const ManifestContext& context);

// Writes DIR/sweep.json through a temporary file and a rename, so that concurrent shards (which
// write the same content) and readers never see half a file.
void write_manifest(const std::string& directory, const nlohmann::json& manifest);

}  // namespace mssph::sweep
