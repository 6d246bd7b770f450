// Physics case: the viscous decay of a shear wave against Stokes' solution, the effective
// viscosity of the paper's eq. 3 across the viscosity sweep's range (README.md beside this file).
#include "framework/case_functions.hpp"
#include "framework/fits.hpp"
#include "physics/shear_decay/shear_decay.hpp"

#include <limits>
#include <map>

namespace mssph::validation {
namespace {

// Over the full run's three spacings, each halving the last, mu_eff / mu converges monotonically
// at an apparent order of at least 1/2, and its Richardson limit lies within 5 % of 1: half the
// case's tolerance, since at a fixed h / dx only the particle error is left (README.md).
constexpr double kSmallestApparentOrder = 0.5;
constexpr double kLimitTolerance = 0.05;

}  // namespace

CaseResult run_shear_decay_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "shear wave decay")) return *skipped;
  // The 40 cm block at 10 spacings (--quick, for 2 CPU cores), and at 10, 20 and 40 (full); the
  // viscosities span configs/sweep_viscosity.json's two decades.
  const std::vector<double> spacings =
      context.quick ? std::vector<double>{0.04} : std::vector<double>{0.04, 0.02, 0.01};
  const std::vector<double> viscosities = {0.2, 2.0, 20.0};
  std::map<double, std::vector<double>> ratios_by_viscosity;  // mu_eff / mu at each spacing
  for (const double dx : spacings) {
    std::vector<double> ratio;
    for (const double mu : viscosities) {
      const ShearDecayMeasurement m = measure_shear_decay(context.physics_backend, shear_decay_scene(dx, mu, 0.5));
      const std::string label = "dx = " + exact(dx) + " m, mu = " + exact(mu) + " Pa s: ";
      result.checks.push_back(relative_check(label + "effective viscosity", "Pa s", mu, m.effective_viscosity, 0.10));
      result.checks.push_back(bound_check(label + "profile L2 error at the end", "-", m.profile_error, 0.10));
      result.details += label + "mu_eff / mu " + exact(m.effective_viscosity / mu) + ", A(end) / A(0) " +
                        exact(m.decay) + ", " + std::to_string(m.particles) + " particles.\n";
      result.series.push_back({"profile_dx" + exact(dx) + "_mu" + exact(mu),
                               "height above the block's bottom [m]",
                               m.height,
                               {{"u_x measured [m/s]", m.profile}, {"u_x Stokes [m/s]", m.analytic}}});
      ratio.push_back(m.effective_viscosity / mu);
      ratios_by_viscosity[mu].push_back(m.effective_viscosity / mu);
    }
    result.series.push_back({"calibration_dx" + exact(dx),
                             "scene viscosity mu [Pa s]",
                             viscosities,
                             {{"effective over scene viscosity", ratio}, {"expected", std::vector<double>(3, 1.0)}}});
  }
  if (spacings.size() == 3) {
    for (const auto& [mu, ratio] : ratios_by_viscosity) {
      const GridConvergence g =
          grid_convergence({spacings[0], spacings[1], spacings[2]}, {ratio[0], ratio[1], ratio[2]});
      const std::string label = "mu = " + exact(mu) + " Pa s: ";
      result.checks.push_back(range_check(label + "apparent order of mu_eff / mu over the three spacings (converges)",
                                          "-", kSmallestApparentOrder, std::numeric_limits<double>::infinity(),
                                          g.order));
      result.checks.push_back(relative_check(label + "mu_eff / mu extrapolated to dx -> 0 at h = 2 dx (Richardson)",
                                             "-", 1.0, g.limit, kLimitTolerance));
    }
  }
  result.resolution = context.quick ? "block 10 dx (dx = 4 cm)" : "block 10, 20 and 40 dx (dx = 4, 2, 1 cm)";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
