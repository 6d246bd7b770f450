#pragma once
// What a backend cannot run, found from the scene alone before anything is built, so that the
// error names the scene file and the JSON path of the value (and a run of millions of particles
// is refused before its set-up, not after).
#include "config/scene.hpp"

#include <string>

namespace mssph::cli {

// Throws InputError "<scene file>: <JSON pointer>: ..." when `backend` cannot run `scene`: the
// float32 backends (cpu, cuda) damp only deformable bodies held by fixed regions.
void check_backend_supports(const Scene& scene, const std::string& backend);

}  // namespace mssph::cli
