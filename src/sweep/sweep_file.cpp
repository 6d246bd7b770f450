#include "sweep/sweep_file.hpp"

#include "config/json_reader.hpp"
#include "config/strict_json.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <set>
#include <sstream>

namespace mssph::sweep {
namespace {

// Parameter and sweep names label table columns, file names and plot axes: "." and ".." would
// name a folder's self or parent (a sweep named ".." would write into results/ itself).
bool is_plain_name(const std::string& name) {
  if (name == "." || name == "..") return false;
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

// Column names of the summary that a parameter must not take.
const std::set<std::string> kReservedColumns{"index", "point", "seed", "state"};

std::string last_path_token(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<nlohmann::json> read_range(const JsonReader& range, ValueScale scale) {
  range.allow_only({"from", "to", "count"});
  const Interval allowed = scale == ValueScale::log ? Interval::positive() : Interval::any();
  const double from = range.number("from", allowed);
  const double to = range.number("to", allowed);
  if (from == to) range.fail("to", "expected a value other than \"from\" (a range of one value is a \"values\" list)");
  const long long count = range.integer_or("count", 0, Interval::closed(2, kMaxSweepPoints));
  if (count == 0) range.fail("count", "missing required key (the number of values, at least 2)");
  std::vector<nlohmann::json> values;
  for (double v : range_values(scale, from, to, count)) {
    // Values closer than the 10 digits kept would run one point twice under two names.
    if (!values.empty() && values.back().get<double>() == v) {
      range.fail("count", std::to_string(count) + " values from " + nlohmann::json(from).dump() + " to " +
                              nlohmann::json(to).dump() + " round to equal values at 10 significant digits (" +
                              std::to_string(values.size() - 1) + " and " + std::to_string(values.size()) +
                              " are both " + nlohmann::json(v).dump() + "); give fewer values or a wider range");
    }
    values.emplace_back(v);
  }
  return values;
}

SweepParameter read_parameter(const JsonReader& reader) {
  reader.allow_only({"path", "name", "values", "linear", "log"});
  SweepParameter p;
  p.pointer = reader.pointer();
  p.path = reader.string("path");
  if (p.path.empty() || p.path == "/")
    reader.fail("path", "expected a scene JSON path such as \"materials/gel/young_modulus\"");
  if (p.path.front() == '/') p.path.erase(0, 1);  // as --set, with or without the leading '/'
  if (p.path == kSeedPath) {
    reader.fail("path", std::string("\"") + kSeedPath + "\" is set by \"repetitions\"; list seeds there");
  }
  p.name = reader.string_or("name", last_path_token(p.path));
  if (!is_plain_name(p.name)) {
    reader.fail(reader.has("name") ? "name" : "path",
                "the parameter's name \"" + p.name + "\" must be letters, digits, '_', '-' or '.' (set \"name\")");
  }
  if (kReservedColumns.count(p.name)) {
    reader.fail(reader.has("name") ? "name" : "path",
                "the name \"" + p.name + "\" is taken by a summary column; give the parameter another \"name\"");
  }
  const int given = int(reader.has("values")) + int(reader.has("linear")) + int(reader.has("log"));
  if (given != 1) {
    reader.fail_here("expected exactly one of \"values\" (a list), \"linear\" or \"log\" (a range {from, to, count})");
  }
  if (reader.has("values")) {
    const JsonReader list = reader.child("values");
    const std::vector<JsonReader> elements = list.elements();
    if (elements.empty()) list.fail_here("expected at least one value, got an empty list");
    std::set<nlohmann::json> seen;  // one lookup per value: a list of a million values is read in a second
    for (const JsonReader& e : elements) {
      if (e.value().is_null() || e.value().is_object())
        e.fail_here("expected a scene value, got " + describe_json(e.value()));
      if (!seen.insert(e.value()).second)
        e.fail_here("duplicate value " + describe_json(e.value()) + " (it would run the same point twice)");
      p.values.push_back(e.value());
    }
  } else if (reader.has("linear")) {
    p.scale = ValueScale::linear;
    p.values = read_range(reader.child("linear"), ValueScale::linear);
  } else {
    p.scale = ValueScale::log;
    p.values = read_range(reader.child("log"), ValueScale::log);
  }
  return p;
}

std::vector<long long> read_seeds(const JsonReader& repetitions) {
  repetitions.allow_only({"seeds"});
  const JsonReader list = repetitions.child("seeds");
  std::vector<long long> seeds;
  for (const JsonReader& e : list.elements()) {
    // Seeds as the scene takes them: integers 0 to 2^63 - 1, written 3 or 3.0 (configs/README.md).
    const nlohmann::json& v = e.value();
    const double d = v.is_number() ? v.get<double>() : -1.0;
    if (!v.is_number() || d < 0.0 || std::trunc(d) != d || d >= 9223372036854775808.0) {
      e.fail_here("expected a seed, an integer >= 0, got " + describe_json(v));
    }
    const long long seed = v.is_number_float() ? static_cast<long long>(d) : v.get<long long>();
    if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end())
      e.fail_here("duplicate seed " + std::to_string(seed));
    seeds.push_back(seed);
  }
  if (seeds.empty()) list.fail_here("expected at least one seed, got an empty list");
  return seeds;
}

std::vector<std::string> read_metrics(const JsonReader& root, const std::vector<std::string>& known) {
  if (!root.has("metrics")) return known;
  const JsonReader list = root.child("metrics");
  std::string known_list;
  for (const std::string& k : known) known_list += (known_list.empty() ? "" : ", ") + k;
  std::vector<std::string> metrics;
  for (const JsonReader& e : list.elements()) {
    if (!e.value().is_string()) e.fail_here("expected a metric name, got " + describe_json(e.value()));
    const std::string name = e.value().get<std::string>();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      e.fail_here("unknown metric \"" + name + "\"; known metrics: " + known_list);
    }
    if (std::find(metrics.begin(), metrics.end(), name) != metrics.end())
      e.fail_here("metric \"" + name + "\" listed twice");
    metrics.push_back(name);
  }
  if (metrics.empty()) list.fail_here("expected at least one metric (leave \"metrics\" out for all of them)");
  return metrics;
}

// The points of the sweep, counted before any is made: a grid of 1e10 points, or one whose count
// overflows 64 bits, is refused with its count instead of exhausting memory.
void check_point_count(const JsonReader& root, const SweepFile& sweep) {
  long double count = 1.0L;  // exact up to 2^64 (a 64-bit significand)
  std::string factors;
  for (const SweepParameter& p : sweep.parameters) {
    if (sweep.combine == Combine::zip && !factors.empty()) break;  // zip: as many as one parameter's values
    count *= static_cast<long double>(p.values.size());
    factors += (factors.empty() ? "" : " x ") + std::to_string(p.values.size()) + " " + p.name;
  }
  if (sweep.combine == Combine::zip) factors += " zipped";
  if (!sweep.seeds.empty()) {
    count *= static_cast<long double>(sweep.seeds.size());
    factors += " x " + std::to_string(sweep.seeds.size()) + " seeds";
  }
  if (count > static_cast<long double>(kMaxSweepPoints)) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(0) << count;
    root.fail("parameters", "the sweep has " + text.str() + " points (" + factors + "); at most " +
                                std::to_string(kMaxSweepPoints) + " are allowed");
  }
}

}  // namespace

const char* to_string(ValueScale scale) {
  switch (scale) {
    case ValueScale::list:
      return "list";
    case ValueScale::linear:
      return "linear";
    case ValueScale::log:
      return "log";
  }
  return "?";
}

std::vector<double> range_values(ValueScale scale, double from, double to, long long count) {
  std::vector<double> values;
  for (long long i = 0; i < count; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(count - 1);
    double v = scale == ValueScale::log ? from * std::pow(to / from, f) : from + (to - from) * f;
    if (i == 0) v = from;
    if (i == count - 1) v = to;
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    values.push_back(std::strtod(text, nullptr));
  }
  return values;
}

SweepFile load_sweep_file(const std::string& path, const std::vector<std::string>& known_metrics) {
  SweepFile sweep;
  sweep.source_file = path;
  sweep.document = read_json_file(path, "sweep file");
  const JsonReader root(sweep.document, path);
  if (!sweep.document.is_object()) root.fail_here("expected a sweep object");
  root.allow_only(
      {"$schema", "name", "description", "scene", "set", "parameters", "combine", "repetitions", "metrics"});
  root.string_or("$schema", "");  // for editors only
  sweep.name = root.string("name");
  if (!is_plain_name(sweep.name))
    root.fail("name",
              "expected a name of letters, digits, '_', '-' or '.', other than \".\" and \"..\" (it names "
              "jobs and files)");
  sweep.description = root.string_or("description", "");

  const std::string scene = root.string("scene");
  std::filesystem::path scene_path(scene);
  if (scene_path.is_relative()) scene_path = std::filesystem::path(path).parent_path() / scene_path;
  sweep.scene_path = scene_path.lexically_normal().string();
  if (!std::filesystem::is_regular_file(sweep.scene_path)) {
    root.fail("scene", "no scene file at " + sweep.scene_path + " (a relative path starts at the sweep file's folder)");
  }

  if (const auto fixed = root.optional_child("set")) {
    for (const auto& [key, value] : fixed->members()) {
      if (value.value().is_null()) value.fail_here("expected a scene value, got null");
      sweep.fixed_overrides.push_back(key + "=" + value.value().dump());
    }
  }

  const JsonReader parameters = root.child("parameters");
  for (const JsonReader& p : parameters.elements()) {
    SweepParameter parameter = read_parameter(p);
    for (const SweepParameter& earlier : sweep.parameters) {
      if (earlier.name == parameter.name)
        p.fail_here("a second parameter named \"" + parameter.name + "\" (set \"name\")");
      if (earlier.path == parameter.path) p.fail("path", "\"" + parameter.path + "\" is swept twice");
    }
    if (std::find(known_metrics.begin(), known_metrics.end(), parameter.name) != known_metrics.end()) {
      p.fail_here("the name \"" + parameter.name + "\" is a metric's; give the parameter another \"name\"");
    }
    sweep.parameters.push_back(std::move(parameter));
  }
  if (sweep.parameters.empty()) parameters.fail_here("expected at least one parameter, got an empty list");

  sweep.combine = root.choice_or("combine", "product", {"product", "zip"}) == "zip" ? Combine::zip : Combine::product;
  if (sweep.combine == Combine::zip) {
    for (const SweepParameter& p : sweep.parameters) {
      if (p.values.size() != sweep.parameters.front().values.size()) {
        root.fail("combine", "\"zip\" pairs the i-th values of every parameter, so each needs as many values; " +
                                 sweep.parameters.front().name + " has " +
                                 std::to_string(sweep.parameters.front().values.size()) + ", " + p.name + " has " +
                                 std::to_string(p.values.size()));
      }
    }
  }
  if (const auto repetitions = root.optional_child("repetitions")) sweep.seeds = read_seeds(*repetitions);
  check_point_count(root, sweep);
  // A fixed value under a swept path would be overwritten at every point: almost surely a mistake.
  if (const auto fixed = root.optional_child("set")) {
    for (const auto& [key, value] : fixed->members()) {
      const std::string bare = !key.empty() && key.front() == '/' ? key.substr(1) : key;
      const bool swept = std::any_of(sweep.parameters.begin(), sweep.parameters.end(),
                                     [&](const SweepParameter& p) { return p.path == bare; });
      if (swept || (bare == kSeedPath && !sweep.seeds.empty())) {
        value.fail_here("\"" + bare + "\" is swept (by \"parameters\" or \"repetitions\"); remove it from \"set\"");
      }
    }
  }
  sweep.metrics = read_metrics(root, known_metrics);
  return sweep;
}

}  // namespace mssph::sweep
