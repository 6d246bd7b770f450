// Physics case: the drag of an impulsively started plate against Stokes' first problem, the
// viscosity between bodies (README.md beside this file).
#include "framework/case_functions.hpp"
#include "framework/convergence.hpp"
#include "physics/plate_shear/plate_shear.hpp"

#include <cmath>
#include <map>

namespace mssph::validation {

CaseResult run_plate_shear_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "plate drag")) return *skipped;
  // The 20 cm layer at 20 spacings (--quick, for 2 CPU cores), and at 20 and 40 (full).
  const std::vector<double> spacings = context.quick ? std::vector<double>{0.01} : std::vector<double>{0.01, 0.005};
  std::map<double, std::vector<double>> errors_by_viscosity;  // |drag / Stokes - 1| at each spacing
  for (const double dx : spacings) {
    for (const double mu : {10.0, 100.0}) {
      const PlateShearMeasurement m = measure_plate_shear(context.physics_backend, plate_shear_scene(dx, mu));
      const std::string label = "dx = " + exact(dx) + " m, mu = " + exact(mu) + " Pa s: ";
      result.checks.push_back(
          relative_check(label + "drag over Stokes' mu U A / sqrt(pi nu t)", "-", 1.0, m.ratio, 0.10));
      errors_by_viscosity[mu].push_back(std::abs(m.ratio - 1.0));
      result.details += label + "ratio " + exact(m.ratio) + " (spread " + exact(m.ratio_spread) + "), " +
                        std::to_string(m.particles) + " particles.\n";
      result.series.push_back({"drag_dx" + exact(dx) + "_mu" + exact(mu),
                               "time [s]",
                               m.time,
                               {{"fluid's force on the plate [N]", m.force}, {"Stokes [N]", m.expected}}});
    }
  }
  // With the spacing halved the drag's error shrinks (an observed order above 0), as in the
  // convergence suite.
  if (spacings.size() > 1) {
    for (const auto& [mu, errors] : errors_by_viscosity) {
      result.checks.push_back(observed_order_check(
          "mu = " + exact(mu) + " Pa s: observed order of the drag's error (shrinks)", spacings, errors, 0.0));
    }
  }
  result.resolution = context.quick ? "layer 20 dx (dx = 1 cm)" : "layer 20 and 40 dx (dx = 1 cm, 5 mm)";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
