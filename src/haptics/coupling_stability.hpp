#pragma once
// Start-up check of the haptic gains against the explicit stability bound of a mass-spring-
// damper integrated by semi-implicit Euler at step h (docs/model.md):
//   K h^2 + 2 B h < 4 m   (translation),   Kr h^2 + 2 Br h < 4 I_min   (rotation).
// For the proxy, h is the longer of dt and the haptic period (the coupling wrench is held from
// tick to tick), m its mass and I_min its smallest principal inertia. For a handle the hand or
// the proxy moves (free and scripted trajectories), h is the haptic period, m and I the device's,
// and K, B every spring-damper on it: the coupling as the device feels it (Kt times the
// workspace scale and force_scale, Kr times torque_scale), the hand's, and its own damping.
// A violated bound is a warning: the run may still be stable, or show the growth in its
// /haptics energy balance.
#include "config/haptics_config.hpp"
#include "haptics/proxy_predictor.hpp"

#include <string>
#include <vector>

namespace mssph {

std::vector<std::string> coupling_stability_warnings(const HapticsConfig& config, const std::string& proxy_name,
                                                     const ProxyModel& proxy, double dt);

}  // namespace mssph
