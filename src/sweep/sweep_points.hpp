#pragma once
// The points of a sweep: every combination (product or zip) of the parameters' values, times
// every repetition seed, each an ordinary scene with --set overrides. A point is named by a hash
// of the scene it runs, so the same point has the same log file in every run of the sweep, on
// every machine, and a changed scene or override is a different point.
#include "sweep/sweep_file.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mssph::sweep {

struct SweepPoint {
  std::size_t index = 0;  // in expansion order: the first parameter varies slowest, the seed fastest
  std::vector<std::pair<std::string, nlohmann::json>> parameters;  // name and value, in parameter order
  std::optional<long long> seed;                                   // with repetitions
  // What `mssph run` gets as --set, in order: the sweep file's "set", the command line's --set,
  // the parameter values, the seed.
  std::vector<std::string> overrides;
  std::string hash;  // point_hash of the scene after the overrides; set by validate_points

  // "young_modulus=200000 poisson_ratio=0.3 seed=1"
  std::string describe() const;
  // "point-<hash>.h5"
  std::string log_name() const;
};

// All points of the sweep, without their hashes (validate_points sets them).
std::vector<SweepPoint> expand_points(const SweepFile& sweep, const std::vector<std::string>& command_line_overrides);

// Loads every point's scene through the scene loader, exactly as `mssph run` would, and names the
// point by its hash. The first point the loader rejects throws an InputError naming the sweep
// file, the point and the loader's reason (scene file, JSON path, what was expected). So does a
// command-line --set of a swept path.
void validate_points(const SweepFile& sweep, const std::vector<std::string>& command_line_overrides,
                     std::vector<SweepPoint>& points);

// 64-bit FNV-1a of the scene document's compact JSON (keys sorted), as 16 hex digits. The run
// log's `config` attribute is that document, so a log's point name can be checked from the log.
std::string point_hash(const nlohmann::json& scene_document);

// 64-bit FNV-1a of the bytes, as 16 hex digits.
std::string fnv1a_64_hex(std::string_view bytes);

}  // namespace mssph::sweep
