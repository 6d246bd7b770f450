#pragma once
// A cantilever sagging under its own weight: the static deflection against Euler-Bernoulli beam
// theory (Timoshenko and Gere, Mechanics of Materials, cantilever under uniform load):
// w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E I), w(L) = q L^4 / (8 E I), with q = rho g A the
// weight per length and I = H^4 / 12 for a square section of side H. Shared by the physics and
// convergence cases and tests/deformable/cantilever_test.cpp; the beam and its scene also by
// physics/cantilever_frequency.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The beam of validation/physics/cantilever/scene.json: free length L (its box minus the three
// clamp layers at the scene's spacing), square section of side H, and its material, SI units.
struct CantileverBeam {
  double length = 0.0;
  double side = 0.0;
  double young_modulus = 0.0;
  double poisson_ratio = 0.0;
  double density = 0.0;
  double gravity = 0.0;  // |g|

  // P-wave speed c_p = sqrt((lambda + 2 mu) / rho) [m/s]: the elastic time-step bound is 0.25 h / c_p.
  double p_wave_speed() const;
  // Euler-Bernoulli first bending mode of a cantilever, omega_1 = 1.8751^2 sqrt(E I / (rho A L^4))
  // (Timoshenko, Vibration Problems in Engineering; 1.8751 is the first root of
  // cos(bL) cosh(bL) = -1) [rad/s].
  double first_bending_omega() const;
};
CantileverBeam cantilever_beam();

// The cantilever scene at spacing dx, clamped by three fixed layers of dx behind x = 0, with
// dt = 0.2 h / c_p (h = 2 dx; inside the elastic bound 0.25 h / c_p), the given mass-proportional
// damping rate [1/s] and duration [s], and kernel-gradient correction on or off.
Scene cantilever_scene(const CantileverBeam& beam, double dx, double damping, double duration, bool correction);

struct CantileverMeasurement {
  double tip = 0.0;              // mean deflection of the last particle layer [m]
  double euler_bernoulli = 0.0;  // w at that layer's x = L - dx / 2 [m]
  // Timoshenko's shear deflection there, q (L x - x^2 / 2) / (kappa G A) with kappa = 5/6
  // (Timoshenko and Gere; rectangular section) [m]
  double shear_deflection = 0.0;
  // Fastest particle at the end [m/s]: the sag is a static one only if the beam is at rest.
  double final_max_speed = 0.0;
  // The speed under which the sag has settled to 1 %: a particle moving at v while the slowest
  // mode decays at rate r still moves v / r. Under the damping 2 omega_1 a mode of frequency
  // omega decays at omega_1 (1 - sqrt(1 - (omega / omega_1)^2)) or faster, which is above
  // omega_1 / 2 while the SPH beam's first mode is within 13 % of Euler-Bernoulli's (its sag
  // within 30 %): so v <= 0.01 w_EB(L) omega_1 / 2 [m/s].
  double rest_speed = 0.0;
  std::size_t fixed_particles = 0;
  std::size_t particles = 0;
  std::size_t steps = 0;
  std::vector<double> x, deflection, expected;  // per particle layer along the beam [m]
};

// The beam run at spacing dx, with kernel-gradient correction on or off, until it rests:
// mass-proportional damping at 2 omega_1 makes the first bending mode critically damped, and
// 12 / omega_1 of simulated time brings it to rest within 0.1 %.
CantileverMeasurement measure_cantilever(const std::string& backend, double dx, bool correction);

}  // namespace mssph::validation
