#pragma once
// Turns a validated scene into particles: samples each body's shape on the lattice, places it,
// applies the seeded jitter, computes masses and rigid-body mass properties, and rejects scenes
// that cannot be simulated (empty or overlapping bodies) with an InputError.
#include "config/scene.hpp"
#include "particle_setup.hpp"

namespace mssph {

ParticleSetup build_particles(const Scene& scene);

}  // namespace mssph
