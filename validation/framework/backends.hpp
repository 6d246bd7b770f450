#pragma once
// Which backends can run on this machine, and where the cases' scene files are.
#include <string>

namespace mssph::validation {

// "" when the named backend can run here, else why not (no CUDA build, no GPU).
std::string why_backend_cannot_run(const std::string& name);

// The validation/ folder: $MSSPH_VALIDATION_DIR if set, else the source tree's.
std::string validation_dir();

// The absolute path of a file given relative to validation/, e.g. "physics/hydrostatic/scene.json".
std::string validation_file(const std::string& relative);

}  // namespace mssph::validation
