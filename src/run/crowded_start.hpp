#pragma once
// A start-up check of how the bodies' lattices meet: particles of two bodies closer than a
// spacing (but not overlapping, which the scene builder refuses) start compressed, and the fluid
// or solid between them is pushed apart in the first steps, an impulse no physics asked for. A
// container whose inner size is not a whole number of spacings does this to the fluid in it.
#include "model/particle_setup.hpp"

#include <string>
#include <vector>

namespace mssph {

// One warning per pair of bodies, one of them moving, whose particles start closer than
// 0.95 dx, less what the lattice jitter (a fraction of dx per axis) may move two particles
// together, 2 sqrt(3) jitter dx; none when that leaves nothing to check.
std::vector<std::string> crowded_start_warnings(const ParticleSetup& setup, double jitter);

}  // namespace mssph
