// Physics case: a sphere's impact on an elastic block against Hertz's impact theory (README.md
// beside this file).
#include "framework/case_functions.hpp"
#include "hertz_impact.hpp"

#include <cmath>

namespace mssph::validation {

CaseResult run_hertz_impact_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "Hertz impact")) return *skipped;
  // dx = 2 cm (--quick, d* = 2 dx) and 1 cm (full, d* = 4 dx).
  const std::vector<double> spacings = context.quick ? std::vector<double>{0.02} : std::vector<double>{0.02, 0.01};
  for (const double dx : spacings) {
    const HertzImpactMeasurement m = measure_hertz_impact(context.physics_backend, hertz_impact_scene(dx));
    const HertzImpact hertz = hertz_impact(m.mass, m.speed, m.stiffness, kPulseFraction);
    const double tolerance = hertz_impact_tolerance(hertz.max_indentation, dx);
    const std::string label = "dx = " + exact(dx) + " m: ";
    result.checks.push_back(
        relative_check(label + "maximum indentation", "m", hertz.max_indentation, m.max_indentation, tolerance));
    result.checks.push_back(relative_check(label + "peak force", "N", hertz.peak_force, m.peak_force, tolerance));
    result.checks.push_back(relative_check(label + "force pulse above 5 % of its peak", "s", hertz.duration_above,
                                           m.duration_above, tolerance));
    const double contact_radius = std::sqrt(m.radius * hertz.max_indentation);
    result.details +=
        label + std::to_string(m.particles) + " particles; d* = " + exact(hertz.max_indentation / dx).substr(0, 5) +
        " dx, contact radius sqrt(R d*) = " + exact(contact_radius / dx).substr(0, 5) +
        " dx (a / R = " + exact(contact_radius / m.radius).substr(0, 5) +
        "); Hertz contact duration 2.94 d* / V = " + exact(hertz.duration) +
        " s; restitution (rebound over impact speed) " + exact(m.rebound_speed / m.speed).substr(0, 5) + ".\n";
    result.series.push_back({"force_dx" + exact(dx), "time [s]", m.time, {{"force on the sphere [N]", m.force}}});
    result.series.push_back({"indentation_dx" + exact(dx), "time [s]", m.time, {{"indentation [m]", m.indentation}}});
  }
  result.resolution =
      context.quick ? "dx = 2 cm (maximum indentation 2 dx)" : "dx = 2 and 1 cm (maximum indentation 2 and 4 dx)";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
