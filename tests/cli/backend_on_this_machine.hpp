#pragma once
// Whether `mssph run --backend NAME` can run here: every build has the host backends; cuda needs
// the CUDA backend built in and a device. Tests of the cuda backend skip cleanly otherwise.
#include <string>

#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

namespace mssph::test {

inline bool backend_runs_here(const std::string& backend) {
  if (backend != "cuda") return true;
#ifdef MSSPH_HAVE_CUDA_BACKEND
  return !kernels::cuda_devices().empty();
#else
  return false;
#endif
}

}  // namespace mssph::test
