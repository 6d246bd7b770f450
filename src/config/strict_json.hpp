#pragma once
// The one JSON reader of mssph's input files (scenes, sweeps, benchmark results) and of --set
// values. Strict where JSON leaves things open: a duplicate key, a number beyond a double and
// nesting deeper than kMaxJsonDepth are refused, each error naming the source and the JSON
// pointer of the offending value, e.g.
//   configs/drop.json: /bodies/ball/density: duplicate key 'density' (JSON leaves its meaning
//   undefined; keep one)
// Parsing takes time and memory in proportion to the text (no step looks back at what was read)
// and never recurses, so no input can overflow the call stack.
#include "util/errors.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace mssph {

// Arrays and objects nested deeper than this are refused: mssph's files need a few levels, and
// the JSON library's serialisation, copies and comparisons recurse once per level.
inline constexpr std::size_t kMaxJsonDepth = 64;

// Text that is not JSON at all (a syntax error), as opposed to JSON that breaks one of the rules
// above: --set takes the first kind as a plain string.
class JsonSyntaxError : public InputError {
 public:
  using InputError::InputError;
};

// Parses `text`; `source` names it in errors ("<source>:<line>:<column>: invalid JSON: ..." for a
// syntax error, "<source>: <pointer>: ..." for the rest). Throws InputError.
nlohmann::json parse_strict_json(const std::string& text, const std::string& source);

// Reads `path` with read_input_file (bounded, one read) and parses it strictly. `what` names the
// file's role in errors, e.g. "scene file". Throws InputError.
nlohmann::json read_json_file(const std::string& path, const std::string& what);

}  // namespace mssph
