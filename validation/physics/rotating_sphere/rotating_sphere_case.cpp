// Physics case: the viscous torque on a rotating sphere against Stokes (README.md beside this file).
#include "framework/case_functions.hpp"
#include "framework/convergence.hpp"
#include "physics/rotating_sphere/rotating_sphere.hpp"

#include <cmath>
#include <map>

namespace mssph::validation {

namespace {

// One run of the case: the sphere's radius R = 5 cm in spacings, the kernel support h / dx, the
// viscosities it turns in and the tolerance on its torque (0: reported, and checked only through
// the convergence of its support's runs).
struct Resolution {
  double spacings;
  double support;
  std::vector<double> viscosities;  // [Pa s]
  double tolerance;
};

// --quick (for 2 CPU cores): 6 dx at the scene default h = 2 dx, 10 Pa s. Full: the default
// support at 10 and 20 dx (what a sweep's scenes run), and h = 3 dx at 10 and 20 dx in both
// viscosities, whose torque converges to Kirchhoff's (README.md, "Why two supports").
std::vector<Resolution> resolutions(bool quick) {
  if (quick) return {{6.0, 2.0, {10.0}, 0.20}};
  return {{10.0, 2.0, {10.0}, 0.20},
          {20.0, 2.0, {10.0}, 0.10},
          {10.0, 3.0, {10.0, 100.0}, 0.0},
          {20.0, 3.0, {10.0, 100.0}, 0.10}};
}

// Between the h = 3 dx runs at 10 and 20 dx the torque's error shrinks at an observed order of at
// least 1/2 (with h halved, the finer error at most 2^-1/2 of the coarser).
constexpr double kConvergenceSupport = 3.0;
constexpr double kSmallestObservedOrder = 0.5;

// The torque's relative errors at the convergence support's spacings, coarse to fine.
struct ErrorsBySpacing {
  std::vector<double> spacing;  // [m]
  std::vector<double> error;    // [-]
};

}  // namespace

CaseResult run_rotating_sphere_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "torque on the rotating sphere")) return *skipped;
  std::map<double, ErrorsBySpacing> converging;  // per viscosity
  for (const Resolution& r : resolutions(context.quick)) {
    const double dx = kRotatingSphereRadius / r.spacings;
    for (const double mu : r.viscosities) {
      // Re = rho omega R^2 / mu = 0.25 at both viscosities (omega 1 and 10 rad/s): the SPH torque
      // depends on the strain the flow has carried, which Re sets per viscous time (decision 058).
      const double omega =
          0.25 * mu / (kRotatingSphereFluidDensity * kRotatingSphereRadius * kRotatingSphereRadius);  // [rad/s]
      const RotatingSphereMeasurement m =
          measure_rotating_sphere(context.physics_backend, rotating_sphere_scene(dx, r.support, mu, omega), omega);
      const std::string label = "R = " + exact(r.spacings) + " dx, h = " + exact(r.support) + " dx, mu = " + exact(mu) +
                                " Pa s, omega = " + exact(omega) + " rad/s: ";
      if (r.support == kConvergenceSupport) {
        converging[mu].spacing.push_back(dx);
        converging[mu].error.push_back(std::abs(m.torque / m.expected_torque - 1.0));
      }
      if (r.tolerance > 0.0) {
        result.checks.push_back(
            relative_check(label + "torque about z", "N m", m.expected_torque, m.torque, r.tolerance));
      }
      result.checks.push_back(bound_check(label + "torque change over the last three fifths (settled)", "-",
                                          std::abs(m.torque / m.torque_earlier - 1.0), 0.02));
      result.checks.push_back(bound_check(label + "Reynolds number rho omega R^2 / mu", "-", m.reynolds, 0.5));
      result.series.push_back(
          {"torque_R" + exact(r.spacings) + "_h" + exact(r.support) + "dx_mu" + exact(mu),
           "time [s]",
           m.time,
           {{"fluid torque about z [N m]", m.torque_history},
            {"Stokes torque with wall factor [N m]", std::vector<double>(m.time.size(), m.expected_torque)}}});
      result.details += label + "measured " + exact(m.torque) + " N m, expected " + exact(m.expected_torque) +
                        " N m (wall factor " + exact(m.wall_factor) + "), ratio " +
                        exact(m.torque / m.expected_torque) + ", sampled radii " + exact(m.radius) +
                        " m (sphere) and " + exact(m.container_radius) + " m (container), " +
                        std::to_string(m.particles) + " particles, largest |omega - omega*| / omega " +
                        exact(m.omega_deviation) + ".\n";
    }
  }
  for (const auto& [mu, runs] : converging) {
    result.checks.push_back(observed_order_check("h = " + exact(kConvergenceSupport) + " dx, mu = " + exact(mu) +
                                                     " Pa s: observed order of the torque's error (converges)",
                                                 runs.spacing, runs.error, kSmallestObservedOrder));
  }
  result.resolution = context.quick ? "sphere radius 6 dx (dx = 8.3 mm), h = 2 dx"
                                    : "sphere radius 10 and 20 dx at h = 2 dx and at h = 3 dx";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
