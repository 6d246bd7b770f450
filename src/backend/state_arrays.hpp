#pragma once
// A run's state as named arrays of plain numbers: what a backend, the haptic loop and the driver
// save into a checkpoint and restore from it (`mssph run --checkpoint-interval`, `--restart`).
// The run log writes each array as a dataset of its own type (io/checkpoint_io.hpp), so that a
// restored float is the same bits as the saved one. Getting an array checks its presence, type
// and length: a checkpoint of another scene or backend is refused with the array's name, never
// read as something else.
#include "util/errors.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace mssph {

class StateArrays {
 public:
  using Array =
      std::variant<std::vector<double>, std::vector<float>, std::vector<std::int64_t>, std::vector<std::uint8_t>>;

  template <class T>
  void put(const std::string& name, std::vector<T> values) {
    arrays_[name] = Array(std::move(values));
  }
  void put_scalar(const std::string& name, double value) { put(name, std::vector<double>{value}); }
  void put_count(const std::string& name, std::int64_t value) { put(name, std::vector<std::int64_t>{value}); }

  // The array `name` of element type T and, when given, `expected_size` elements. Throws InputError
  // naming the array otherwise.
  template <class T>
  const std::vector<T>& get(const std::string& name, std::optional<std::size_t> expected_size = std::nullopt) const {
    const auto it = arrays_.find(name);
    if (it == arrays_.end()) throw InputError("checkpoint: no array \"" + name + "\"");
    const auto* values = std::get_if<std::vector<T>>(&it->second);
    if (!values) throw InputError("checkpoint: array \"" + name + "\" has another element type than " + type_name<T>());
    if (expected_size && values->size() != *expected_size) {
      throw InputError("checkpoint: array \"" + name + "\" has " + std::to_string(values->size()) + " values, " +
                       std::to_string(*expected_size) +
                       " expected (a log of another scene, or of a version that saved other state?)");
    }
    return *values;
  }
  double scalar(const std::string& name) const { return get<double>(name, 1).front(); }
  std::int64_t count(const std::string& name) const { return get<std::int64_t>(name, 1).front(); }

  // Every array of `part` under "<prefix>/<its name>", e.g. a backend's under "backend"; moved,
  // not copied: a large scene's arrays are tens of megabytes.
  void add_part(const std::string& prefix, StateArrays part) {
    for (auto& [name, values] : part.arrays_) arrays_[prefix + "/" + name] = std::move(values);
  }
  // The arrays under "<prefix>/", with the prefix taken off.
  StateArrays part(const std::string& prefix) const {
    StateArrays out;
    const std::string start = prefix + "/";
    for (const auto& [name, values] : arrays_) {
      if (name.compare(0, start.size(), start) == 0) out.arrays_[name.substr(start.size())] = values;
    }
    return out;
  }

  const std::map<std::string, Array>& arrays() const { return arrays_; }
  void set(const std::string& name, Array values) { arrays_[name] = std::move(values); }

  template <class T>
  static std::string type_name() {
    if constexpr (std::is_same_v<T, double>) return "float64";
    if constexpr (std::is_same_v<T, float>) return "float32";
    if constexpr (std::is_same_v<T, std::int64_t>) return "int64";
    return "uint8";
  }

 private:
  std::map<std::string, Array> arrays_;
};

}  // namespace mssph
