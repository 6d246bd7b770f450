#pragma once
// The damping ratio of the free bar's first longitudinal mode under the Kelvin-Voigt viscous
// stress (scene key viscous_modulus, eta [Pa s]): with sigma = E eps + eta eps_dot every mode of
// angular frequency omega decays with damping ratio zeta = eta omega / (2 E) (the stiffness-
// proportional damping of Chopra, Dynamics of Structures, 4th ed. 2012, sec. 11.4, with
// beta = eta / E). Measured by the logarithmic decrement of the end-to-end elongation's peaks, on
// any backend. Shared by the physics case and tests/deformable/viscous_bar_test.cpp.
#include "backend/backend.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

struct ViscousBarMeasurement {
  double damping_ratio = 0.0;      // zeta from the logarithmic decrement of the peaks [-]
  double angular_frequency = 0.0;  // omega_n = sqrt(omega_d^2 + sigma^2) of the measured mode [rad/s]
  double expected_ratio = 0.0;     // eta omega_n / (2 E) [-]
  std::size_t peaks = 0;           // peaks fitted (the release's own peak left out)
  std::size_t particles = 0;
  std::vector<double> time;        // [s]
  std::vector<double> elongation;  // end-to-end length minus its rest value [m]
};

// The bar of validation/physics/bar_vibration/scene.json with `settings` ("key=value" as --set
// takes them, e.g. its viscous_modulus and spacing), stretched by 1 % along x with lateral
// contraction nu times that, released on `backend` and followed for `periods` periods.
ViscousBarMeasurement measure_viscous_bar(const std::string& backend, const std::vector<std::string>& settings,
                                          double periods);

// The logarithmic decrement's damping ratio and natural frequency of a decaying oscillation:
// one peak per interval between downward zero crossings (the first, the release, left out); a
// least-squares line through log(peak) gives the decay rate sigma = zeta omega_n, the crossings
// the damped frequency omega_d. Returns {zeta, omega_n, peaks}; zeros with fewer than 3 peaks.
struct Decrement {
  double damping_ratio = 0.0;
  double angular_frequency = 0.0;
  std::size_t peaks = 0;
};
Decrement logarithmic_decrement(const std::vector<double>& time, const std::vector<double>& signal);

}  // namespace mssph::validation
