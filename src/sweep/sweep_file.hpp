#pragma once
// A sweep file: a base scene, the scene values to vary (as --set paths), how to combine them,
// repetitions with seeds, and the metrics to collect. Reading is strict like the scene loader's:
// every error names the file, the JSON path and what was expected (exit code 2). The rules are
// stated for editors in configs/sweep.schema.json and documented in configs/README.md.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mssph::sweep {

// How a parameter's values were given; a plot draws log ranges on log axes.
enum class ValueScale { list, linear, log };
const char* to_string(ValueScale scale);

struct SweepParameter {
  std::string name;  // column name in the summary and the plots, e.g. "young_modulus"
  std::string path;  // scene JSON path as --set takes it, e.g. "materials/soft_rubber/young_modulus"
  ValueScale scale = ValueScale::list;
  std::vector<nlohmann::json> values;  // in sweep order, at least one
  std::string pointer;                 // where it was defined in the sweep file, e.g. "/parameters/0"
};

enum class Combine { product, zip };

struct SweepFile {
  std::string source_file;  // as given
  nlohmann::json document;  // as read
  std::string name;
  std::string description;
  std::string scene_path;                    // resolved against the sweep file's folder
  std::vector<std::string> fixed_overrides;  // "set": applied to every point before its parameters
  std::vector<SweepParameter> parameters;
  Combine combine = Combine::product;
  std::vector<long long> seeds;      // repetitions: one point per seed and parameter combination; empty: none
  std::vector<std::string> metrics;  // the metrics to collect, in order
};

// The most points a sweep may have (parameter combinations times seeds), and the most values a
// range may give: each point is a run, and each point's scene is loaded before any runs.
inline constexpr long long kMaxSweepPoints = 100000;

// The path every repetition's seed is written to.
inline constexpr const char* kSeedPath = "simulation/seed";

// Reads and validates `path`. `known_metrics` are the metric names the summary can compute; the
// default when the file names none. Throws InputError.
SweepFile load_sweep_file(const std::string& path, const std::vector<std::string>& known_metrics);

// Values of a linear or log range: `count` values from `from` to `to` inclusive, each rounded to
// 10 significant digits so that the same range gives the same values (and point names) on every
// machine, whatever the last bits of pow() there.
std::vector<double> range_values(ValueScale scale, double from, double to, long long count);

}  // namespace mssph::sweep
