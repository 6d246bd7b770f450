#pragma once
// Whether `mssph run --backend NAME` can run here: every build has the host backends; cuda needs
// the CUDA backend built in and a device. Tests of the cuda backend skip cleanly otherwise.
#include "backend_factory/backend_factory.hpp"

#include <string>

namespace mssph::test {

inline bool backend_runs_here(const std::string& backend) { return why_backend_cannot_run(backend).empty(); }

}  // namespace mssph::test
