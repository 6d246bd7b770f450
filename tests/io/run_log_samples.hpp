#pragma once
// Sample content for run-log tests: metadata with non-ASCII text, and row values that are
// distinct per row and column, so a misplaced, dropped or repeated row changes what is read.
#include "io/run_log.hpp"

#include <array>
#include <cstddef>
#include <string>

namespace mssph::test {

inline RunMetadata sample_metadata() {
  RunMetadata m;
  m.version = "9.8.7";
  m.git_commit = "0123456789ab-dirty";
  m.backend = "reference";
  m.device = "Test CPU (2 threads)";
  m.precision = "float64";
  m.scene_name = "round_trip";
  m.config_path = "configs/round_trip.json";
  m.config_json = "{\n  \"name\": \"round_trip\",\n  \"note\": \"\xCF\x81\xE2\x82\x80 = 1000 kg/m^3\"\n}";
  m.config_file = "{\"note\": \"\xCF\x81\xE2\x82\x80 = 1000 kg/m^3\", \"name\": \"round_trip\"}\n";
  m.seed = 1234567890123LL;
  m.command_line = "mssph run configs/round_trip.json --set simulation/dt=1e-4";
  return m;
}

inline double scalar_row(std::size_t i) { return 0.125 * static_cast<double>(i) + 1.0 / static_cast<double>(i + 3); }

inline std::array<double, 3> vector_row(std::size_t i) {
  const double x = static_cast<double>(i);
  return {x, -0.5 * x, 1.0 / (x + 7.0)};
}

}  // namespace mssph::test
