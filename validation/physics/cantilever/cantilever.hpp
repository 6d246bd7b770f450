#pragma once
// A cantilever sagging under its own weight: the static deflection against Euler-Bernoulli beam
// theory (Timoshenko and Gere, Mechanics of Materials, cantilever under uniform load):
// w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E I), w(L) = q L^4 / (8 E I), with q = rho g A the
// weight per length and I = H^4 / 12 for a square section of side H. Shared by the physics and
// convergence cases and tests/deformable/cantilever_test.cpp.
#include <string>
#include <vector>

namespace mssph::validation {

struct CantileverMeasurement {
  double tip = 0.0;             // mean deflection of the last particle layer [m]
  double euler_bernoulli = 0.0;  // w at that layer's x = L - dx / 2 [m]
  // Timoshenko's shear deflection there, q (L x - x^2 / 2) / (kappa G A) with kappa = 5/6
  // (Timoshenko and Gere; rectangular section) [m]
  double shear_deflection = 0.0;
  std::size_t fixed_particles = 0;
  std::size_t particles = 0;
  std::size_t steps = 0;
  std::vector<double> x, deflection, expected;  // per particle layer along the beam [m]
};

// The beam of validation/physics/cantilever/scene.json (length L = its box minus the three
// clamp layers) run at spacing dx, with kernel-gradient correction on or off, until it rests:
// dt = 0.2 h / c_p (c_p = sqrt((lambda + 2 mu) / rho), inside the elastic bound 0.25 h / c_p),
// mass-proportional damping at 2 omega_1 (first bending mode, omega_1 = 1.875^2 sqrt(E I /
// (rho A L^4))) makes it critically damped, and 12 / omega_1 of simulated time brings it to rest
// within 0.1 %.
CantileverMeasurement measure_cantilever(const std::string& backend, double dx, bool correction);

}  // namespace mssph::validation
