#pragma once
// A torque-free rigid body tumbling in free space (validation/physics/torque_free_spin): its
// angular momentum L is constant (Euler's equations without torque; Landau and Lifshitz,
// Mechanics, section 36) and so is its rotational energy L . omega / 2. Shared by the physics
// case and tests/reference/rigid_physics_test.cpp.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

struct SpinMeasurement {
  double worst_momentum_error = 0.0;   // max over samples of |L - L0| / |L0|
  double worst_energy_drift = 0.0;     // max over samples of |E - E0| / E0
  double largest_turn_degrees = 0.0;   // how far omega in body axes swung from its start: did it tumble?
  double final_linear_momentum = 0.0;  // |p| at the end [kg m/s]
  std::vector<double> time, momentum_error, energy_drift;
};

// Runs the scene's first body for the scene's duration, sampling every 100 steps.
SpinMeasurement measure_torque_free_spin(const std::string& backend, const Scene& scene);

}  // namespace mssph::validation
