#pragma once
// Running a float32 backend (cpu, cuda) beside the reference on the same scene.
#include "backend_factory/backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "framework/backends.hpp"
#include "kernels/sphere_drops/sphere_drops.hpp"
#include "model/scene_builder.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mssph::testing {

// Whether the named backend can run here; the cuda backend needs both the build and a GPU.
inline bool backend_runs_here(const std::string& name) { return why_backend_cannot_run(name).empty(); }

#define MSSPH_SKIP_WITHOUT(backend_name)                                                          \
  if (!mssph::testing::backend_runs_here(backend_name)) {                                         \
    GTEST_SKIP() << "backend " << (backend_name) << " cannot run here (no CUDA build or no GPU)"; \
  }

// A shipped scene at a coarse spacing, as CI runs it.
inline ParticleSetup coarse_scene(const std::string& config, double duration,
                                  const std::vector<std::string>& extra = {}) {
  return validation::shipped_scene(config, 0.04, duration, extra);
}

inline std::size_t find_body(const ParticleSetup& setup, const std::string& name) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == name) return b;
  }
  throw std::invalid_argument("no body " + name);
}

}  // namespace mssph::testing
