#pragma once
// A rigid body held to a prescribed motion by a controller while the fluid acts on it: the
// stepping loop and the averaging windows that the towed and the turned sphere share.
#include "backend/backend.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace mssph::validation {

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N]
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // [N m]
};

// A quantity q read from the body after each step, averaged where the run has settled.
struct ControlledRun {
  double mean = 0.0;                  // of q over the last two fifths of the steps
  double mean_earlier = 0.0;          // of q over the fifth before them: settled when close
  double largest_deviation = 0.0;     // of `deviation` over the last two fifths
  std::vector<double> time, history;  // q every 1 % of the run [s]
};

// Runs `steps` steps of `backend`. Before each, the rigid body's external wrench is
// control(state), from its state after the step before (its initial state first); after each,
// q = quantity(state) and deviation(state) are read.
ControlledRun run_controlled(Backend& backend, std::size_t body, std::size_t steps,
                             const std::function<Wrench(const BodyState&)>& control,
                             const std::function<double(const BodyState&)>& quantity,
                             const std::function<double(const BodyState&)>& deviation);

}  // namespace mssph::validation
