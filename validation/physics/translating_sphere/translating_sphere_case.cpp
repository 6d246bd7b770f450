// Physics case: the Stokes drag on a towed sphere, extrapolated from closed cubes to an unbounded
// fluid (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/translating_sphere/translating_sphere.hpp"

#include <cmath>

namespace mssph::validation {
namespace {

std::vector<double> halved(std::vector<double> values) {
  for (double& v : values) v *= 0.5;
  return values;
}

}  // namespace

CaseResult run_translating_sphere_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "drag on the towed sphere")) return *skipped;
  // Sphere radius R = 5 cm in spacings: --quick 3 (for 2 CPU cores), full 6 and 8; cube sides in
  // radii: --quick 8 and 12, full 8, 12 and 16 (each an even number of spacings).
  const std::vector<double> radii_in_spacings =
      context.quick ? std::vector<double>{3.0} : std::vector<double>{6.0, 8.0};
  const std::vector<double> sides_in_radii =
      context.quick ? std::vector<double>{8.0, 12.0} : std::vector<double>{8.0, 12.0, 16.0};
  const double mu = 100.0;  // [Pa s]: Re = rho V R / mu <= 0.001 at 1 and 2 mm/s
  const auto [k_low, k_high] = cube_wall_coefficient_bracket();
  for (const double spacings : radii_in_spacings) {
    const double dx = 0.05 / spacings;
    const bool finest = spacings == radii_in_spacings.back();
    const std::string label = "R = " + exact(spacings) + " dx: ";
    std::vector<LinearDrag> cubes;
    for (const double sides : sides_in_radii) {
      const LinearDrag d = measure_linear_drag(context.physics_backend, dx, mu, sides * 0.05);
      const std::string cube = label + "cube " + exact(sides) + " R: ";
      result.checks.push_back(range_check(cube + "linear drag over Stokes' within the concentric spheres' bracket", "-",
                                          d.slow.factor_low, d.slow.factor_high, d.factor));
      for (const TowedSphereMeasurement* m : {&d.slow, &d.fast}) {
        const std::string run = cube + "V = " + exact(m == &d.slow ? 1.0 : 2.0) + " mm/s: ";
        result.checks.push_back(bound_check(run + "drag change over the last three fifths (settled)", "-",
                                            std::abs(m->drag / m->drag_earlier - 1.0), 0.02));
        result.checks.push_back(bound_check(run + "Reynolds number rho V R / mu", "-", m->reynolds, 0.5));
        result.details += run + "drag " + exact(m->drag) + " N, 6 pi mu R V " + exact(m->stokes_drag) +
                          " N, sampled radius " + exact(m->radius) + " m, " + std::to_string(m->particles) +
                          " particles, largest |v - V| / V " + exact(m->speed_deviation) + ".\n";
      }
      result.details += cube + "linear drag " + exact(d.factor) + " of 6 pi mu R V, bracket [" +
                        exact(d.slow.factor_low) + ", " + exact(d.slow.factor_high) +
                        "]; the part that does not change with the speed, at 1 mm/s: " + exact(d.offset) + ".\n";
      result.series.push_back({"drag_R" + exact(spacings) + "_L" + exact(sides),
                               "time [s]",
                               d.slow.time,
                               {{"fluid drag at 1 mm/s [N]", d.slow.drag_history},
                                {"fluid drag at 2 mm/s, halved [N]", halved(d.fast.drag_history)},
                                {"Stokes drag at 1 mm/s, circumscribed sphere [N]",
                                 std::vector<double>(d.slow.time.size(), d.slow.factor_low * d.slow.stokes_drag)},
                                {"Stokes drag at 1 mm/s, inscribed sphere [N]",
                                 std::vector<double>(d.slow.time.size(), d.slow.factor_high * d.slow.stokes_drag)}}});
      cubes.push_back(d);
    }
    const UnboundedDrag unbounded = extrapolate_to_unbounded(cubes);
    // 10 % at the finest spacing (the issue's); a coarser one is reported within 20 %.
    result.checks.push_back(relative_check(label + "linear drag extrapolated to an unbounded fluid over 6 pi mu R V",
                                           "-", 1.0, unbounded.drag_over_stokes, finest ? 0.10 : 0.20));
    result.checks.push_back(range_check(label + "wall coefficient k of F_S / F = 1 - k R / L", "-", k_low, k_high,
                                        unbounded.wall_coefficient));
  }
  result.resolution = context.quick ? "sphere radius 3 dx (dx = 1.67 cm), cubes of 8 and 12 R"
                                    : "sphere radius 6 and 8 dx, cubes of 8, 12 and 16 R";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
