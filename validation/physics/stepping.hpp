#pragma once
// What the measuring code of several cases shares: a body found by name, a sampled sphere's
// radius, and steps counted in time.
#include "backend/backend.hpp"
#include "config/scene.hpp"
#include "model/particle_setup.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mssph::validation {

// The index of the body `name`; a scene without it is a broken case (std::runtime_error).
inline std::size_t body_index(const ParticleSetup& setup, const std::string& name, const Scene& scene) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == name) return b;
  }
  throw std::runtime_error(scene.source_file + ": this measurement needs a body \"" + name + "\"");
}

// The radius of a sphere sampled as `sites` lattice sites of volume dx^3 (BodySetup::lattice_sites) [m].
inline double sampled_sphere_radius(std::size_t sites, double dx) {
  return std::cbrt(3.0 * static_cast<double>(sites) * dx * dx * dx / (4.0 * std::numbers::pi));
}

// Whole steps of `dt` in `seconds`.
inline std::size_t steps_for(double seconds, double dt) { return static_cast<std::size_t>(std::llround(seconds / dt)); }

inline void run_steps(Backend& backend, std::size_t steps) {
  for (std::size_t s = 0; s < steps; ++s) backend.step();
}

}  // namespace mssph::validation
