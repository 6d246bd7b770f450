#include "config/strict_json.hpp"

#include "config/input_file.hpp"
#include "config/json_reader.hpp"

#include <utility>
#include <vector>

namespace mssph {
namespace {

using nlohmann::json;

// The line and column of a byte offset, which is what an editor shows.
std::string line_and_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// Builds the document from the parser's events (the SAX interface of nlohmann-json), refusing
// what parse_strict_json refuses. A duplicate key is found by one lookup in the object being
// built; the frames say where the parser is, for naming a value by its JSON pointer.
class StrictBuilder {
 public:
  StrictBuilder(json& root, const std::string& text, const std::string& source)
      : root_(root), text_(text), source_(source) {}

  bool null() { return add(nullptr); }
  bool boolean(bool value) { return add(value); }
  bool number_integer(json::number_integer_t value) { return add(value); }
  bool number_unsigned(json::number_unsigned_t value) { return add(value); }
  bool number_float(json::number_float_t value, const json::string_t& /*text*/) { return add(value); }
  bool string(json::string_t& value) { return add(std::move(value)); }
  bool binary(json::binary_t& value) { return add(std::move(value)); }

  bool start_object(std::size_t /*elements*/) { return open(json::object()); }
  bool start_array(std::size_t /*elements*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& key) {
    Frame& top = frames_.back();
    top.key = std::move(key);
    if (top.container->contains(top.key)) {
      const std::string pointer = pointer_here();
      throw InputError(
          source_ + ": " + pointer + ": duplicate key '" + top.key + "' (JSON leaves its meaning undefined; keep one)",
          pointer);
    }
    return true;
  }

  bool parse_error(std::size_t position, const std::string& /*last_token*/, const nlohmann::detail::exception& e) {
    if (e.id == 406) {
      // out_of_range 406: a number beyond a double's range, e.g. 1e400, in the value being read.
      const std::string pointer = pointer_here();
      throw InputError(source_ + ": " + pointer + ": " + e.what() + " (numbers must be finite doubles, |x| < 1.8e308)",
                       pointer);
    }
    throw JsonSyntaxError(source_ + ":" + line_and_column(text_, position) + ": invalid JSON: " + e.what());
  }

 private:
  struct Frame {
    json* container;
    std::string key;  // objects: the member being read
  };

  // The JSON pointer of the value being read: in an array, the element after the last one added,
  // or the last one while a frame above is still open.
  std::string pointer_here() const {
    std::string pointer;
    for (std::size_t level = 0; level < frames_.size(); ++level) {
      const Frame& f = frames_[level];
      pointer += '/';
      if (f.container->is_object()) {
        pointer += escape_pointer_token(f.key);
      } else {
        const bool inside_last = level + 1 < frames_.size();
        pointer += std::to_string(f.container->size() - (inside_last ? 1 : 0));
      }
    }
    return pointer.empty() ? "/" : pointer;
  }

  // Stores `value` where the parser is and returns where it went.
  template <typename Value>
  json* place(Value&& value) {
    if (frames_.empty()) {
      root_ = json(std::forward<Value>(value));
      return &root_;
    }
    Frame& top = frames_.back();
    if (top.container->is_array()) {
      top.container->push_back(json(std::forward<Value>(value)));
      return &top.container->back();
    }
    json& slot = (*top.container)[top.key];
    slot = json(std::forward<Value>(value));
    return &slot;
  }

  template <typename Value>
  bool add(Value&& value) {
    place(std::forward<Value>(value));
    return true;
  }

  bool open(json&& empty) {
    if (frames_.size() >= kMaxJsonDepth) {
      const std::string pointer = pointer_here();
      throw InputError(source_ + ": " + pointer + ": arrays and objects nested more than " +
                           std::to_string(kMaxJsonDepth) + " levels deep (mssph's files need a few)",
                       pointer);
    }
    json* container = place(std::move(empty));
    frames_.push_back({container, {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  json& root_;
  const std::string& text_;
  const std::string& source_;
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json parse_strict_json(const std::string& text, const std::string& source) {
  json document;
  StrictBuilder builder(document, text, source);
  json::sax_parse(text, &builder);
  return document;
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  return parse_strict_json(read_input_file(path, what), path);
}

}  // namespace mssph
