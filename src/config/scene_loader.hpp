#pragma once
// Reads a scene file, applies `--set path=value` overrides and validates everything before any
// output exists. Every failure is an InputError naming the file, the JSON path and what was
// expected.
#include "config/scene.hpp"
#include "util/errors.hpp"

#include <string>
#include <vector>

namespace mssph {

// Applies one override "a/b/c=value" to `document`. The value is parsed as JSON when it is valid
// JSON (numbers, arrays, true/false, quoted strings), else taken as a plain string. The parent of
// the last path component must exist.
void apply_override(nlohmann::json& document, const std::string& assignment);

// Parses and validates an already loaded document. `file` is used in error messages.
Scene parse_scene(const nlohmann::json& document, const std::string& file);

// Reads `path`, applies the overrides in order and validates the result.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// `e` with a note naming the --set override that gave the rejected value (its JSON pointer), if
// one did: for checks made after loading, e.g. of the particles a scene builds.
InputError noting_override(const InputError& e, const std::vector<std::string>& overrides);

// The same for a scene file's text (`path` names it in messages and locates a recorded
// trajectory): strict JSON (no duplicate keys, no number beyond a double), then as above.
Scene parse_scene_text(const std::string& text, const std::string& path,
                       const std::vector<std::string>& overrides = {});

}  // namespace mssph
