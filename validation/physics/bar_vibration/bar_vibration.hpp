#pragma once
// A free elastic bar released from a uniform 1 % stretch (uniaxial stress) vibrates at its first
// longitudinal frequency f = (1 / 2L) sqrt(E / rho) (Graff, Wave Motion in Elastic Solids, 1975,
// section 2.1) and, without damping, keeps its energy; with mass-proportional damping at rate
// gamma its vibration energy decays as exp(-gamma t). On the reference backend (the strain energy
// is its internal state). Shared by the physics case and tests/deformable/bar_vibration_test.cpp.
#include "reference_backend.hpp"

#include <vector>

namespace mssph::validation {

// The bar of validation/physics/bar_vibration/scene.json with the given damping rate [1/s],
// stretched by 1 % along x with lateral contraction nu times that.
reference::ReferenceBackend stretched_bar(double damping);

// The bar's total energy and elongation, sampled every step.
struct BarHistory {
  std::vector<double> time;
  std::vector<double> energy;      // strain energy at x_n + kinetic energy at v_n [J]
  std::vector<double> elongation;  // end-to-end length minus its rest value [m]
};
BarHistory run_bar(reference::ReferenceBackend& backend, double duration);

// The mean period between successive downward zero crossings of the elongation (0 if fewer than two).
double measured_period(const BarHistory& history);

// Largest |E / E0 - 1| over the history.
double energy_drift(const BarHistory& history);

// The least-squares slope of log(energy) against time [1/s].
double energy_decay_rate(const BarHistory& history);

// 2 L / sqrt(E / rho) of the scene's bar [s].
double bar_period(const reference::ReferenceBackend& backend);

}  // namespace mssph::validation
