#include "haptics/coupling_stability.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <sstream>

namespace mssph {
namespace {

struct Bound {
  const char* what;          // "proxy translation", ...
  double stiffness;          // [N/m] or [N m/rad]
  double damping;            // [N s/m] or [N m s/rad]
  double inertia;            // [kg] or [kg m^2]
  double step;               // [s]
  const char* inertia_name;  // "m", "I_min"
  const char* inertia_unit;
};

void check(const Bound& b, const std::string& proxy_name, std::vector<std::string>& warnings) {
  const double lhs = b.stiffness * b.step * b.step + 2.0 * b.damping * b.step;
  const double rhs = 4.0 * b.inertia;
  if (lhs < rhs) return;
  std::ostringstream out;
  out << "proxy \"" << proxy_name << "\": " << b.what << " gains exceed the explicit stability bound K h^2 + 2 B h < 4 "
      << b.inertia_name << ": K = " << b.stiffness << ", B = " << b.damping << ", h = " << b.step << " s give " << lhs
      << " >= 4 " << b.inertia_name << " = " << rhs << " (" << b.inertia_name << " = " << b.inertia << " "
      << b.inertia_unit << "); the coupling may go unstable: lower the gains or the step";
  warnings.push_back(out.str());
}

}  // namespace

std::vector<std::string> coupling_stability_warnings(const HapticsConfig& config, const std::string& proxy_name,
                                                     const ProxyModel& proxy, double dt) {
  std::vector<std::string> warnings;
  const SpringDamperGains& c = config.coupling;
  const double period = 1.0 / config.haptic_rate_hz;
  const double proxy_step = std::max(dt, period);
  const double smallest_inertia =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(proxy.inertia_body).eigenvalues().minCoeff();
  check({"translational coupling", c.linear_stiffness, c.linear_damping, proxy.mass, proxy_step, "m", "kg"}, proxy_name,
        warnings);
  check(
      {"rotational coupling", c.angular_stiffness, c.angular_damping, smallest_inertia, proxy_step, "I_min", "kg m^2"},
      proxy_name, warnings);

  if (config.trajectory.source == TrajectorySource::recorded) return warnings;  // the handle is not simulated
  const DeviceConfig& d = config.device;
  const bool scripted = config.trajectory.source == TrajectorySource::scripted;
  const SpringDamperGains hand = scripted ? config.trajectory.hand : SpringDamperGains{};
  const double linear_gain = d.workspace.scale * d.force_scale;
  check({"device handle translational (coupling + hand + device damping)",
         linear_gain * c.linear_stiffness + hand.linear_stiffness,
         linear_gain * c.linear_damping + hand.linear_damping + d.linear_damping, d.mass, period, "m", "kg"},
        proxy_name, warnings);
  check({"device handle rotational (coupling + hand + device damping)",
         d.torque_scale * c.angular_stiffness + hand.angular_stiffness,
         d.torque_scale * c.angular_damping + hand.angular_damping + d.angular_damping, d.inertia, period, "I_min",
         "kg m^2"},
        proxy_name, warnings);
  return warnings;
}

}  // namespace mssph
