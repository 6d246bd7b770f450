#include "bench/benchmark_results.hpp"

#include "util/errors.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace mssph::bench {
namespace {

double seconds_per(const std::string& unit, const std::string& where) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  if (unit == "s") return 1.0;
  throw InputError(where + "/time_unit: expected ns, us, ms or s, got \"" + unit + "\"");
}

std::string as_text(const nlohmann::json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

// A positive, finite number at entry[key], or InputError naming where.
double positive(const nlohmann::json& entry, const std::string& key, const std::string& where) {
  if (!entry[key].is_number()) throw InputError(where + "/" + key + ": expected a number");
  const double value = entry[key].get<double>();
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(where + "/" + key + ": expected a positive finite number, got " + entry[key].dump());
  }
  return value;
}

}  // namespace

BenchmarkResults read_benchmark_results(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open benchmark results");
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not JSON (" + e.what() + ")");
  }
  const std::string hint = " (expected Google Benchmark JSON, as `mssph bench --out FILE.json` writes)";
  if (!document.is_object() || !document.contains("context") || !document["context"].is_object()) {
    throw InputError(path + ": no \"context\" object" + hint);
  }
  if (!document.contains("benchmarks") || !document["benchmarks"].is_array()) {
    throw InputError(path + ": no \"benchmarks\" array" + hint);
  }
  BenchmarkResults results;
  results.path = path;
  for (const auto& [key, value] : document["context"].items()) results.context[key] = as_text(value);
  const nlohmann::json& entries = document["benchmarks"];
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const nlohmann::json& entry = entries[i];
    const std::string where = path + ": /benchmarks/" + std::to_string(i);
    if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string()) {
      throw InputError(where + ": expected an object with a \"name\" string");
    }
    // Repetitions are "iteration" runs; "aggregate" runs summarise them.
    if (entry.value("run_type", std::string("iteration")) != "iteration") continue;
    const std::string name = entry.contains("run_name") && entry["run_name"].is_string()
                                 ? entry["run_name"].get<std::string>()
                                 : entry["name"].get<std::string>();
    if (entry.value("error_occurred", false)) {
      results.errors.push_back(name + ": " + entry.value("error_message", std::string("error")));
      continue;
    }
    if (!entry.contains("real_time") || !entry["real_time"].is_number()) {
      throw InputError(where + "/real_time: expected a number");
    }
    if (!entry.contains("time_unit") || !entry["time_unit"].is_string()) {
      throw InputError(where + "/time_unit: expected a string");
    }
    // Step benchmarks time batches of steps; their step_seconds counter is the same time per step.
    const double seconds =
        entry.contains("step_seconds")
            ? positive(entry, "step_seconds", where)
            : positive(entry, "real_time", where) * seconds_per(entry["time_unit"].get<std::string>(), where);
    if (entry.contains("instructions_per_step")) {
      results.instructions_per_step[name] = positive(entry, "instructions_per_step", where);
      if (entry.contains("ll_misses_per_step") && entry["ll_misses_per_step"].is_number()) {
        results.ll_misses_per_step[name] = entry["ll_misses_per_step"].get<double>();
      }
    }
    auto [it, inserted] = results.seconds.try_emplace(name);
    if (inserted) results.names.push_back(name);
    it->second.push_back(seconds);
  }
  return results;
}

}  // namespace mssph::bench
