#pragma once
// Where `mssph run` writes its log, checked before any output exists: a bad --out is bad input
// (exit code 2) reported in words, not an HDF5 error after the simulation has been set up.
#include <string>

namespace mssph::cli {

// results/runs/<scene>_<backend>.h5, relative to the working directory.
std::string default_output_path(const std::string& scene_name, const std::string& backend_name);

// Throws InputError naming `path` when the run log could not be written there: the path is a
// directory (or ends in '/'), a component of its parent is not a directory, the deepest existing
// parent directory is not writable, or an existing file there is not writable.
void check_output_path(const std::string& path);

}  // namespace mssph::cli
