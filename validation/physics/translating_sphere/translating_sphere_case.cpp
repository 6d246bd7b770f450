// Physics case: the Stokes drag on a towed sphere, extrapolated from closed cubes to an unbounded
// fluid (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/translating_sphere/translating_sphere.hpp"

#include <cmath>

namespace mssph::validation {

CaseResult run_translating_sphere_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "drag on the towed sphere")) return *skipped;
  // Sphere radius R = 5 cm in spacings: --quick 3 (for 2 CPU cores), full 6 and 8; cube sides in
  // radii: --quick 8 and 12, full 8, 12 and 16 (each an even number of spacings).
  const std::vector<double> radii_in_spacings =
      context.quick ? std::vector<double>{3.0} : std::vector<double>{6.0, 8.0};
  const std::vector<double> sides_in_radii =
      context.quick ? std::vector<double>{8.0, 12.0} : std::vector<double>{8.0, 12.0, 16.0};
  const double mu = 100.0;     // [Pa s]
  const double speed = 0.001;  // [m/s]: Re = rho V R / mu = 0.0005
  const auto [k_low, k_high] = cube_wall_coefficient_bracket();
  for (const double spacings : radii_in_spacings) {
    const double dx = 0.05 / spacings;
    const bool finest = spacings == radii_in_spacings.back();
    const std::string label = "R = " + exact(spacings) + " dx: ";
    std::vector<TowedSphereMeasurement> cubes;
    for (const double sides : sides_in_radii) {
      const TowedSphereMeasurement m = measure_translating_sphere(
          context.physics_backend, translating_sphere_scene(dx, mu, sides * 0.05, speed), speed);
      const std::string cube = label + "cube " + exact(sides) + " R: ";
      result.checks.push_back(range_check(cube + "drag over Stokes' within the concentric spheres' bracket", "-",
                                          m.factor_low, m.factor_high, m.drag / m.stokes_drag));
      result.checks.push_back(bound_check(cube + "drag change over the last three fifths (settled)", "-",
                                          std::abs(m.drag / m.drag_earlier - 1.0), 0.02));
      result.checks.push_back(bound_check(cube + "Reynolds number rho V R / mu", "-", m.reynolds, 0.5));
      result.series.push_back(
          {"drag_R" + exact(spacings) + "_L" + exact(sides),
           "time [s]",
           m.time,
           {{"fluid drag [N]", m.drag_history},
            {"Stokes drag, circumscribed sphere [N]", std::vector<double>(m.time.size(), m.factor_low * m.stokes_drag)},
            {"Stokes drag, inscribed sphere [N]", std::vector<double>(m.time.size(), m.factor_high * m.stokes_drag)}}});
      result.details += cube + "drag " + exact(m.drag) + " N, 6 pi mu R V " + exact(m.stokes_drag) + " N, bracket [" +
                        exact(m.factor_low) + ", " + exact(m.factor_high) + "], sampled radius " + exact(m.radius) +
                        " m, " + std::to_string(m.particles) + " particles, largest |v - V| / V " +
                        exact(m.speed_deviation) + ".\n";
      cubes.push_back(m);
    }
    const UnboundedDrag unbounded = extrapolate_to_unbounded(cubes);
    // 10 % at the finest spacing (the issue's); a coarser one is reported within 20 %.
    result.checks.push_back(relative_check(label + "drag extrapolated to an unbounded fluid over 6 pi mu R V", "-", 1.0,
                                           unbounded.drag_over_stokes, finest ? 0.10 : 0.20));
    result.checks.push_back(range_check(label + "wall coefficient k of F_S / F = 1 - k R / L", "-", k_low, k_high,
                                        unbounded.wall_coefficient));
  }
  result.resolution = context.quick ? "sphere radius 3 dx (dx = 1.67 cm), cubes of 8 and 12 R"
                                    : "sphere radius 6 and 8 dx, cubes of 8, 12 and 16 R";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
