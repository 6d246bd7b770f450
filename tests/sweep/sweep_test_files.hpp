#pragma once
// Sweep files written by tests into a temporary folder, with the scene given by absolute path.
#include "temp_dir.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace mssph::test {

inline std::string tiny_scene() { return MSSPH_SOURCE_DIR "/tests/data/tiny_drop.json"; }

// The metric names scripts/analysis/log_metrics.py defines (what `mssph sweep` asks it for).
inline const std::vector<std::string>& test_metrics() {
  static const std::vector<std::string> names{"peak_interaction_force", "time_to_peak", "final_status"};
  return names;
}

// A parameter of a tiny sweep: the ball's density at two values.
inline const nlohmann::json kDensity = {{"path", "bodies/ball/density"}, {"values", {400, 600}}};

// A sweep over the tiny drop: `parameters` as the sweep file's list, `extra` merged at the top.
inline nlohmann::json tiny_sweep(const nlohmann::json& parameters,
                                 const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json sweep{{"name", "test_sweep"}, {"scene", tiny_scene()}, {"parameters", parameters}};
  for (const auto& [key, value] : extra.items()) sweep[key] = value;
  return sweep;
}

inline std::string write_json(const TempDir& dir, const std::string& name, const nlohmann::json& document) {
  const std::string path = (dir / name).string();
  std::ofstream(path) << document.dump(2);
  return path;
}

}  // namespace mssph::test
