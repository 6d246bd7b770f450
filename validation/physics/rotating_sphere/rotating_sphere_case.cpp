// Physics case: the viscous torque on a rotating sphere against Stokes (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/rotating_sphere/rotating_sphere.hpp"

#include <cmath>

namespace mssph::validation {

CaseResult run_rotating_sphere_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "torque on the rotating sphere")) return *skipped;
  // Sphere radius R = 5 cm in spacings: --quick 6 (for 2 CPU cores), full 10 and 20.
  const std::vector<double> radii_in_spacings =
      context.quick ? std::vector<double>{6.0} : std::vector<double>{10.0, 20.0};
  // Two viscosities a decade apart in the full run: the same problem in units of mu omega, so
  // their torques agree to four digits when the torque scales with the viscosity in Pa s. The
  // quick run (CI's time) turns the sphere in the first only.
  const std::vector<double> viscosities = context.quick ? std::vector<double>{10.0} : std::vector<double>{10.0, 100.0};
  for (const double spacings : radii_in_spacings) {
    const double dx = kRotatingSphereRadius / spacings;
    const bool finest = spacings == radii_in_spacings.back();
    for (const double mu : viscosities) {
      // Re = rho omega R^2 / mu = 0.25 at both viscosities (omega 1 and 10 rad/s): the SPH torque
      // depends on the strain the flow has carried, which Re sets per viscous time (decision 058).
      const double omega =
          0.25 * mu / (kRotatingSphereFluidDensity * kRotatingSphereRadius * kRotatingSphereRadius);  // [rad/s]
      const RotatingSphereMeasurement m =
          measure_rotating_sphere(context.physics_backend, rotating_sphere_scene(dx, mu, omega), omega);
      const std::string label =
          "R = " + exact(spacings) + " dx, mu = " + exact(mu) + " Pa s, omega = " + exact(omega) + " rad/s: ";
      // 10 % at the full run's finest spacing (the issue's); a coarser one, and the quick run's,
      // within 20 % (README.md, "Tolerance").
      const double tolerance = finest && !context.quick ? 0.10 : 0.20;
      result.checks.push_back(relative_check(label + "torque about z", "N m", m.expected_torque, m.torque, tolerance));
      result.checks.push_back(bound_check(label + "torque change over the last three fifths (settled)", "-",
                                          std::abs(m.torque / m.torque_earlier - 1.0), 0.02));
      result.checks.push_back(bound_check(label + "Reynolds number rho omega R^2 / mu", "-", m.reynolds, 0.5));
      result.series.push_back(
          {"torque_R" + exact(spacings) + "_mu" + exact(mu),
           "time [s]",
           m.time,
           {{"fluid torque about z [N m]", m.torque_history},
            {"Stokes torque with wall factor [N m]", std::vector<double>(m.time.size(), m.expected_torque)}}});
      result.details += label + "measured " + exact(m.torque) + " N m, expected " + exact(m.expected_torque) +
                        " N m (wall factor " + exact(m.wall_factor) + "), sampled radii " + exact(m.radius) +
                        " m (sphere) and " + exact(m.container_radius) + " m (container), " +
                        std::to_string(m.particles) + " particles, largest |omega - omega*| / omega " +
                        exact(m.omega_deviation) + ".\n";
    }
  }
  result.resolution = context.quick ? "sphere radius 6 dx (dx = 8.3 mm)" : "sphere radius 10 and 20 dx";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
