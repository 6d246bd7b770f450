#pragma once
// The cantilever's first bending frequency: the beam of physics/cantilever, undamped, released
// straight and at rest under gravity, swings about its static sag. Euler-Bernoulli (Timoshenko,
// Vibration Problems in Engineering): f1 = 1.8751^2 / (2 pi L^2) sqrt(E I / (rho A)). Shared by
// the physics case and tests/deformable/cantilever_frequency_test.cpp.
#include <cstddef>
#include <string>
#include <vector>

namespace mssph::validation {

// The frequency of an oscillating signal from its upward crossings of its mean: (n - 1) periods
// between the first and the last of n crossings, each crossing time interpolated linearly
// between samples [1/s]. 0 when there are fewer than two crossings. For a periodic signal any
// level between its extremes gives crossings one period apart, so the mean need not be exact.
double oscillation_frequency(const std::vector<double>& time, const std::vector<double>& signal);

// f1 of Timoshenko's cantilever (shear with kappa = 5/6, and rotary inertia) over Euler-Bernoulli's
// for this beam (L / H = 6, nu = 0.3), from converged finite elements:
// scripts/validation/timoshenko_cantilever.py, which tests/cli/validate_command_test.cpp reruns.
inline constexpr double kTimoshenkoF1Ratio = 0.97868;

struct CantileverVibration {
  double frequency = 0.0;        // measured from the tip's sag [Hz]
  double euler_bernoulli = 0.0;  // f1 of Euler-Bernoulli's cantilever [Hz]
  double max_tip = 0.0;          // largest tip sag [m] (twice the static sag for a pure first mode)
  std::size_t particles = 0;
  std::size_t steps = 0;
  std::vector<double> time, tip;  // the tip's sag (mean over the last particle layer) [s], [m]
};

// The beam of physics/cantilever at spacing dx (dt = 0.2 h / c_p), without damping, released
// straight and at rest under gravity, run for `periods` Euler-Bernoulli periods; the tip's sag
// is sampled about 200 times a period.
CantileverVibration measure_cantilever_vibration(const std::string& backend, double dx, bool correction,
                                                 double periods);

}  // namespace mssph::validation
