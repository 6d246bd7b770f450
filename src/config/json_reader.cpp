#include "config/json_reader.hpp"

#include "util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace mssph {
namespace {

// A message as a terminal can show it: a key may hold a NUL character ("\u0000" in JSON), which
// would otherwise end the message where it is printed as a C string.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\0') {
      out += "\\u0000";
    } else {
      out += c;
    }
  }
  return out;
}

std::string format_number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// Levenshtein distance, to suggest the key a user probably meant.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

bool Interval::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

std::string Interval::describe() const {
  const bool has_lo = std::isfinite(lo);
  const bool has_hi = std::isfinite(hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
           (hi_open ? ")" : "]");
  }
  if (has_lo) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (has_hi) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return "finite";
}

std::string escape_pointer_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string describe_json(const nlohmann::json& value) {
  constexpr std::size_t kLimit = 40;
  // JSON text of a scalar; bytes that are not UTF-8 (a string cut mid-character) shown as U+FFFD.
  const auto escaped = [](const nlohmann::json& scalar) {
    return scalar.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  // One entry per open array or object, with the next member to write.
  struct Open {
    const nlohmann::json* container;
    nlohmann::json::const_iterator next;
  };
  std::vector<Open> open;
  std::string text;
  const auto write = [&](const nlohmann::json& v) {
    if (v.is_structured()) {
      text += v.is_object() ? '{' : '[';
      open.push_back({&v, v.cbegin()});
    } else if (v.is_string() && v.get_ref<const std::string&>().size() > kLimit) {
      text += escaped(v.get_ref<const std::string&>().substr(0, kLimit));  // cut anyway below
    } else {
      text += escaped(v);
    }
  };
  write(value);
  while (!open.empty() && text.size() <= kLimit) {
    Open& top = open.back();
    if (top.next == top.container->cend()) {
      text += top.container->is_object() ? '}' : ']';
      open.pop_back();
      continue;
    }
    if (top.next != top.container->cbegin()) text += ',';
    if (top.container->is_object()) {
      text += escaped(top.next.key()) + ":";
    }
    const nlohmann::json& member = *top.next;
    ++top.next;  // before write(), which may grow `open` and move `top`
    write(member);
  }
  if (text.size() > kLimit) text = text.substr(0, kLimit - 3) + "...";
  return std::string(value.type_name()) + " " + text;
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string pointer)
    : value_(&value), file_(std::move(file)), pointer_(std::move(pointer)) {}

std::string JsonReader::key_pointer(const std::string& key) const { return pointer_ + "/" + escape_pointer_token(key); }

void JsonReader::fail(const std::string& key, const std::string& message) const {
  throw InputError(printable(file_ + ": " + key_pointer(key) + ": " + message), key_pointer(key));
}

void JsonReader::fail_here(const std::string& message) const {
  throw InputError(printable(file_ + ": " + (pointer_.empty() ? std::string("/") : pointer_) + ": " + message),
                   pointer_.empty() ? std::string("/") : pointer_);
}

void JsonReader::allow_only(std::initializer_list<const char*> allowed) const {
  if (!value_->is_object()) fail_here("expected an object, got " + describe_json(*value_));
  for (const auto& item : value_->items()) {
    const std::string& key = item.key();  // a plain name: lambdas capture it (not so a structured binding in Clang 14)
    if (std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) continue;
    std::string message = "unknown key '" + key + "'";
    const char* closest = nullptr;
    std::size_t best = 3;  // suggest only near misses
    for (const char* a : allowed) {
      const std::size_t d = edit_distance(key, a);
      if (d < best) {
        best = d;
        closest = a;
      }
    }
    if (closest) {
      message += " (did you mean '" + std::string(closest) + "'?)";
    } else {
      message += "; allowed keys:";
      for (const char* a : allowed) message += std::string(" ") + a;
    }
    fail(key, message);
  }
}

bool JsonReader::has(const std::string& key) const { return value_->is_object() && value_->contains(key); }

const nlohmann::json& JsonReader::at(const std::string& key) const {
  if (!value_->is_object()) fail_here("expected an object, got " + describe_json(*value_));
  const auto it = value_->find(key);
  if (it == value_->end()) fail(key, "missing required key");
  return *it;
}

JsonReader JsonReader::child(const std::string& key) const { return JsonReader(at(key), file_, key_pointer(key)); }

std::optional<JsonReader> JsonReader::optional_child(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return child(key);
}

std::vector<std::pair<std::string, JsonReader>> JsonReader::members() const {
  if (!value_->is_object()) fail_here("expected an object, got " + describe_json(*value_));
  std::vector<std::pair<std::string, JsonReader>> out;
  for (const auto& [key, value] : value_->items()) {
    out.emplace_back(key, JsonReader(value, file_, key_pointer(key)));
  }
  return out;
}

std::vector<JsonReader> JsonReader::elements() const {
  if (!value_->is_array()) fail_here("expected an array, got " + describe_json(*value_));
  std::vector<JsonReader> out;
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], file_, pointer_ + "/" + std::to_string(i));
  }
  return out;
}

double JsonReader::number(const std::string& key, Interval range) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number()) fail(key, "expected a number " + range.describe() + ", got " + describe_json(v));
  const double x = v.get<double>();
  if (!range.contains(x)) fail(key, "expected a number " + range.describe() + ", got " + format_number(x));
  return x;
}

double JsonReader::number_or(const std::string& key, double fallback, Interval range) const {
  return has(key) ? number(key, range) : fallback;
}

long long JsonReader::integer_or(const std::string& key, long long fallback, Interval range) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = at(key);
  const auto reject = [&] { fail(key, "expected an integer " + range.describe() + ", got " + describe_json(v)); };
  // JSON has one number type: 3 and 3.0 (or 3e0) are the same value, and JSON Schema's "integer"
  // accepts all three, so any number without a fractional part that a long long holds is taken.
  constexpr double kTwoToThe63 = 9223372036854775808.0;
  long long x = 0;
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())) reject();
    x = static_cast<long long>(u);
  } else if (v.is_number_integer()) {
    x = v.get<long long>();
  } else if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!(std::trunc(d) == d && d >= -kTwoToThe63 && d < kTwoToThe63)) reject();
    x = static_cast<long long>(d);
  } else {
    reject();
  }
  if (!range.contains(static_cast<double>(x))) reject();
  return x;
}

bool JsonReader::boolean_or(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = at(key);
  if (!v.is_boolean()) fail(key, "expected true or false, got " + describe_json(v));
  return v.get<bool>();
}

std::string JsonReader::string(const std::string& key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_string()) fail(key, "expected a string, got " + describe_json(v));
  return v.get<std::string>();
}

std::string JsonReader::string_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string JsonReader::choice(const std::string& key, std::initializer_list<const char*> choices) const {
  const nlohmann::json& v = at(key);
  std::string options;
  for (const char* c : choices) options += (options.empty() ? "" : ", ") + std::string("\"") + c + "\"";
  if (!v.is_string()) fail(key, "expected one of " + options + ", got " + describe_json(v));
  const std::string s = v.get<std::string>();
  if (std::none_of(choices.begin(), choices.end(), [&](const char* c) { return s == c; })) {
    fail(key, "expected one of " + options + ", got \"" + s + "\"");
  }
  return s;
}

std::string JsonReader::choice_or(const std::string& key, const std::string& fallback,
                                  std::initializer_list<const char*> choices) const {
  return has(key) ? choice(key, choices) : fallback;
}

Eigen::Vector3d JsonReader::vec3(const std::string& key, Interval range) const {
  const nlohmann::json& v = at(key);
  if (!v.is_array() || v.size() != 3 || !std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_number(); })) {
    fail(key, "expected an array of 3 numbers, got " + describe_json(v));
  }
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    out[i] = v[static_cast<std::size_t>(i)].get<double>();
    if (!range.contains(out[i])) {
      fail(key, "expected each component " + range.describe() + ", got " + format_number(out[i]) + " at index " +
                    std::to_string(i));
    }
  }
  return out;
}

Eigen::Vector3d JsonReader::vec3_or(const std::string& key, const Eigen::Vector3d& fallback, Interval range) const {
  return has(key) ? vec3(key, range) : fallback;
}

Eigen::Quaterniond JsonReader::quaternion_or(const std::string& key, const Eigen::Quaterniond& fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = at(key);
  if (!v.is_array() || v.size() != 4 || !std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_number(); })) {
    fail(key, "expected a quaternion [qx, qy, qz, qw] (4 numbers), got " + describe_json(v));
  }
  const Eigen::Quaterniond q(v[3].get<double>(), v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  const double norm = q.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-6) {
    fail(key, "expected a unit quaternion [qx, qy, qz, qw], got norm " + format_number(norm));
  }
  return q.normalized();
}

}  // namespace mssph
