#pragma once
// Strict, path-aware reading of a JSON document. Every error names the file, the JSON pointer
// of the offending value and what was expected, e.g.
//   configs/drop.json: /bodies/block/poisson_ratio: expected a number in (-1, 0.5), got 0.5
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mssph {

// An allowed interval for a number; open or closed at each end, unbounded by default.
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Interval any() { return {}; }
  static Interval positive() { return {0.0, Interval{}.hi, true, false}; }
  static Interval non_negative() { return {0.0, Interval{}.hi, false, false}; }
  static Interval open(double lo, double hi) { return {lo, hi, true, true}; }
  static Interval closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Interval at_least(double lo) { return {lo, Interval{}.hi, false, false}; }

  bool contains(double x) const;
  std::string describe() const;  // "> 0", "in (-1, 0.5)", ...
};

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string file, std::string pointer = "");

  const std::string& pointer() const { return pointer_; }
  const std::string& file() const { return file_; }
  const nlohmann::json& value() const { return *value_; }

  // Fails on any key of this object not in `allowed`, naming the closest allowed key.
  void allow_only(std::initializer_list<const char*> allowed) const;
  bool has(const std::string& key) const;

  JsonReader child(const std::string& key) const;  // required
  std::optional<JsonReader> optional_child(const std::string& key) const;
  std::vector<std::pair<std::string, JsonReader>> members() const;  // an object's members in order
  std::vector<JsonReader> elements() const;                         // an array's elements

  double number(const std::string& key, Interval range = Interval::any()) const;
  double number_or(const std::string& key, double fallback, Interval range = Interval::any()) const;
  long long integer_or(const std::string& key, long long fallback, Interval range = Interval::any()) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  std::string choice(const std::string& key, std::initializer_list<const char*> choices) const;
  std::string choice_or(const std::string& key, const std::string& fallback,
                        std::initializer_list<const char*> choices) const;
  Eigen::Vector3d vec3(const std::string& key, Interval range = Interval::any()) const;
  Eigen::Vector3d vec3_or(const std::string& key, const Eigen::Vector3d& fallback,
                          Interval range = Interval::any()) const;
  // A unit quaternion stored [qx, qy, qz, qw] (scalar last, like the Virtuose's pose).
  Eigen::Quaterniond quaternion_or(const std::string& key, const Eigen::Quaterniond& fallback) const;

  // Throws InputError "<file>: <pointer>/<key>: <message>".
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  [[noreturn]] void fail_here(const std::string& message) const;

 private:
  const nlohmann::json& at(const std::string& key) const;
  std::string key_pointer(const std::string& key) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string pointer_;
};

// JSON pointer escaping of one key ('~' -> "~0", '/' -> "~1").
std::string escape_pointer_token(const std::string& key);
// A short description of a JSON value's type and content for error messages: the type and the
// start of its compact text, at most 40 characters, written without recursing into the value and
// stopping at the limit, so a value nested deeply or holding millions of elements costs no more
// than a small one ("array [1,2]", "object {\"a\":[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...").
std::string describe_json(const nlohmann::json& value);

}  // namespace mssph
