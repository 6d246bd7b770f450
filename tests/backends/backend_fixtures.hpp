#pragma once
// Running a float32 backend (cpu, cuda) beside the reference on the same scene.
#include "backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "scene/scene_builder.hpp"
#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mssph::testing {

// Whether the named backend can run here; the cuda backend needs both the build and a GPU.
inline bool backend_runs_here(const std::string& name) {
  if (name != "cuda") return true;
#ifdef MSSPH_HAVE_CUDA_BACKEND
  return !kernels::cuda_devices().empty();
#else
  return false;
#endif
}

#define MSSPH_SKIP_WITHOUT(backend_name)                                                              \
  if (!mssph::testing::backend_runs_here(backend_name)) {                                           \
    GTEST_SKIP() << "backend " << (backend_name) << " cannot run here (no CUDA build or no GPU)";    \
  }

// A shipped scene at a coarse spacing, as CI runs it.
inline ParticleSetup coarse_scene(const std::string& config, double duration, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> overrides{"simulation/particle_spacing=0.04", "simulation/duration=" + std::to_string(duration)};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return build_particles(load_scene(std::string(MSSPH_SOURCE_DIR) + "/configs/" + config, overrides));
}

inline std::size_t find_body(const ParticleSetup& setup, const std::string& name) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == name) return b;
  }
  throw std::invalid_argument("no body " + name);
}

// The proxy's interaction force and centre of mass after every step.
struct ProxyTrack {
  std::vector<Eigen::Vector3d> force;
  std::vector<Eigen::Vector3d> position;
};

inline ProxyTrack track_proxy(const std::string& backend_name, const ParticleSetup& setup, std::size_t proxy, std::size_t steps) {
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  ProxyTrack track;
  for (std::size_t s = 0; s < steps; ++s) {
    backend->step();
    const BodyState state = backend->rigid_body_state(proxy);
    track.force.push_back(state.interaction_force);
    track.position.push_back(state.centre_of_mass);
  }
  return track;
}

// Root-mean-square difference of two series of vectors over the largest norm in the reference.
inline double normalised_rms(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& reference) {
  double sum = 0.0;
  double scale = 0.0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    sum += (a[k] - reference[k]).squaredNorm();
    scale = std::max(scale, reference[k].norm());
  }
  return std::sqrt(sum / static_cast<double>(reference.size())) / scale;
}

}  // namespace mssph::testing
