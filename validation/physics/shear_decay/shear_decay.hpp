#pragma once
// The viscous decay of a shear wave in a free block of fluid, measured on any backend. Shared by
// shear_decay_case.cpp and tests/reference/shear_decay_test.cpp.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The scene's fluid bodies "lower" and "upper" stack into a block of height L (z from z0 to
// z0 + L) whose halves move at +U and -U along x: the square wave u(z) = U sign(cos(k (z - z0)))
// with k = pi / L. Its free top and bottom carry no shear stress, as each Fourier mode
// cos((2m + 1) k (z - z0)) of the wave requires, so the incompressible Navier-Stokes equations
// are solved by each mode decaying as exp(-nu (2m + 1)^2 k^2 t), nu = mu / rho0 (Stokes' shear
// wave; e.g. Batchelor, An Introduction to Fluid Dynamics, 1967, sec. 4.3). Sampled 40 times:
// the fundamental's amplitude A(t), the least-squares projection of the particles' u_x on
// cos(k (z - z0)); the viscosity whose decay rate a line through ln A(t) gives,
// mu_eff = -rho0 (d ln A / dt) / k^2; and at the end the profile of u_x in layers one spacing thick
// against the analytic series, as a relative L2 difference.
struct ShearDecayMeasurement {
  double viscosity = 0.0;                         // the scene's mu [Pa s]
  double effective_viscosity = 0.0;               // mu_eff [Pa s]
  double profile_error = 0.0;                     // ||u - u_exact||_2 / ||u_exact||_2 at the end
  double decay = 0.0;                             // A(end) / A(0)
  std::vector<double> time, amplitude;            // [s], [m/s]
  std::vector<double> height, profile, analytic;  // the final profile: z - z0 [m], u_x [m/s]
  std::size_t particles = 0;
};
ShearDecayMeasurement measure_shear_decay(const std::string& backend, const Scene& scene);

// The case's scene at spacing dx and viscosity mu, running for `decay_times` of the
// fundamental's decay time 1 / (nu k^2), with the step the smaller of the scene's, scaled with dx
// (acoustic), and 0.8 of the viscous bound 0.125 h^2 rho0 / mu.
Scene shear_decay_scene(double dx, double viscosity, double decay_times);

}  // namespace mssph::validation
