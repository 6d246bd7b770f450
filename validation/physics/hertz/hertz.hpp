#pragma once
// Hertz contact: a rigid sphere pressed quasi-statically into an elastic block, the two coupled
// only through the interaction forces of paper eq. 7. Hertz (Johnson, Contact Mechanics, 1985,
// eq. 4.22): F = 4/3 E* sqrt(R) d^1.5 with E* = E / (1 - nu^2) for a rigid indenter, d the
// indentation. Shared by the physics case and tests/deformable/hertz_contact_test.cpp.
#include "config/scene.hpp"
#include "model/particle_setup.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph::validation {

// Points on concentric spheres of radii R - dx/2, R - 3 dx/2, ... about `centre`, each sphere
// covered by a Fibonacci spiral at one point per dx^2 of its area; only points below z_max. A
// lattice ball's bottom is a flat facet, which acts as a flat punch; these shells are round.
std::vector<Eigen::Vector3d> spherical_shells(const Eigen::Vector3d& centre, double radius, double dx, double z_max);

// The setup with the particles of body `replaced` swapped for `points`, each taking the fields
// of the body's first particle (a rigid body's rest offsets are the caller's to set).
ParticleSetup with_body_particles(const ParticleSetup& in, std::size_t replaced,
                                  const std::vector<Eigen::Vector3d>& points);

struct Indentation {
  std::vector<double> depth;  // d: indenter travel beyond first geometric contact [m]
  std::vector<double> force;  // F: contact force on the block, upwards [N]
};

// Presses the scene's "indenter" (a boundary sphere, re-sampled as concentric spherical shells
// dx apart: a lattice ball's flat bottom facet would act as a flat punch) into its deformable
// "block" at `speed` [m/s] until d = `deepest` [m], on the reference backend (which lets a
// boundary body be moved by hand). One sample per step.
Indentation press_indenter(const Scene& scene, double speed, double deepest);

// The log-log slope of F(d) and the least-squares prefactor C of F = C d^1.5 over
// d_min <= d <= d_max; min_force is the smallest force there (contact must be made).
struct HertzFit {
  double exponent = 0.0;
  double prefactor = 0.0;
  double min_force = 0.0;
};
HertzFit fit_hertz(const Indentation& curve, double d_min, double d_max);

// 4/3 E* sqrt(R) of the scene's block and indenter.
double hertz_prefactor(const Scene& scene);

}  // namespace mssph::validation

namespace mssph::validation {

// The press and the fit range, in spacings, as the unit test runs them: the sphere moves at
// 0.1 m/s (1.6 % of the shear wave speed) and the block is damped at 200 /s, so that the contact
// stays quasi-static; the contact radius sqrt(R d) grows from 2.5 to 5.6 dx over the fit.
constexpr double kHertzSpeed = 0.1;       // [m/s]
constexpr double kHertzShallowest = 0.5;  // [dx]
constexpr double kHertzDeepest = 2.5;     // [dx]

}  // namespace mssph::validation
