#include "bench/benchmark_results.hpp"

#include "config/input_file.hpp"
#include "config/json_reader.hpp"
#include "config/strict_json.hpp"
#include "util/errors.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace mssph::bench {
namespace {

double seconds_per(const std::string& unit) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  return 1.0;  // "s", the last choice read_benchmark_results allows
}

// A context value as text: a string as it is, a number or true/false as JSON, an array or object
// by describe_json (bounded, whatever its size or depth).
std::string as_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.is_structured() ? describe_json(value) : value.dump();
}

// A positive, finite number at entry[key], or InputError naming where.
double positive(const JsonReader& entry, const std::string& key) {
  const nlohmann::json& value = entry.child(key).value();
  if (!value.is_number() || !(value.get<double>() > 0.0) || !std::isfinite(value.get<double>())) {
    entry.fail(key, "expected a positive finite number, got " + describe_json(value));
  }
  return value.get<double>();
}

}  // namespace

BenchmarkResults read_benchmark_results(const std::string& path) {
  nlohmann::json document;
  try {
    document = read_json_file(path, "benchmark results file");
  } catch (const JsonSyntaxError& e) {
    throw InputError(path + ": not JSON (" + e.what() + ")");
  }
  const JsonReader root(document, path);
  const std::string hint = " (expected Google Benchmark JSON, as `mssph bench --out FILE.json` writes)";
  if (!document.is_object() || !document.contains("context") || !document["context"].is_object()) {
    throw InputError(path + ": no \"context\" object" + hint);
  }
  if (!document.contains("benchmarks") || !document["benchmarks"].is_array()) {
    throw InputError(path + ": no \"benchmarks\" array" + hint);
  }
  BenchmarkResults results;
  results.path = path;
  for (const auto& [key, value] : root.child("context").members()) results.context[key] = as_text(value.value());
  for (const JsonReader& entry : root.child("benchmarks").elements()) {
    if (!entry.value().is_object()) entry.fail_here("expected an object with a \"name\" string");
    const std::string full_name = entry.string("name");
    // Repetitions are "iteration" runs; "aggregate" runs summarise them.
    if (entry.string_or("run_type", "iteration") != "iteration") continue;
    const std::string name = entry.string_or("run_name", full_name);
    if (entry.boolean_or("error_occurred", false)) {
      results.errors.push_back(name + ": " + entry.string_or("error_message", "error"));
      continue;
    }
    const std::string unit = entry.choice("time_unit", {"ns", "us", "ms", "s"});
    // Step benchmarks time batches of steps; their step_seconds counter is the same time per step.
    const double seconds =
        entry.has("step_seconds") ? positive(entry, "step_seconds") : positive(entry, "real_time") * seconds_per(unit);
    if (entry.has("instructions_per_step")) {
      results.instructions_per_step[name] = positive(entry, "instructions_per_step");
      if (entry.has("ll_misses_per_step")) results.ll_misses_per_step[name] = entry.number("ll_misses_per_step");
    }
    auto [it, inserted] = results.seconds.try_emplace(name);
    if (inserted) results.names.push_back(name);
    it->second.push_back(seconds);
  }
  return results;
}

void null_for_values_without_json_literal(const std::string& path) {
  const std::string text = read_input_file(path, "benchmark results file");
  // Outside strings JSON has no capital N or I but in these tokens (true, false, null, numbers).
  static const std::array<std::string_view, 4> kNoLiteral{"-Infinity", "Infinity", "-NaN", "NaN"};
  std::string fixed;
  fixed.reserve(text.size());
  bool in_string = false, escaped = false;
  for (std::size_t k = 0; k < text.size();) {
    const char c = text[k];
    if (in_string) {
      in_string = escaped || c != '"';
      escaped = !escaped && c == '\\';
    } else if (c == '"') {
      in_string = true;
    } else {
      const auto token = std::find_if(kNoLiteral.begin(), kNoLiteral.end(),
                                      [&](std::string_view t) { return text.compare(k, t.size(), t) == 0; });
      if (token != kNoLiteral.end()) {
        fixed += "null";
        k += token->size();
        continue;
      }
    }
    fixed += c;
    ++k;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!(out << fixed) || !out.flush()) throw std::runtime_error(path + ": cannot write");
}

}  // namespace mssph::bench
