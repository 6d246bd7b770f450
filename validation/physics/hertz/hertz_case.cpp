// Physics case: Hertz contact exponent and prefactor (README.md beside this file).
#include "config/scene_loader.hpp"
#include "framework/case_functions.hpp"
#include "hertz.hpp"

#include <cmath>

namespace mssph::validation {

CaseResult run_hertz_case(const CaseContext&) {
  // Reference backend only: the measurement moves a boundary body by hand, which the float32
  // backends do not offer. Same resolution in --quick and full (17k particles, 1375 steps).
  const Scene scene = load_scene(validation_file("physics/hertz/scene.json"));
  const double dx = scene.simulation.particle_spacing;
  const Indentation curve = press_indenter(scene, kHertzSpeed, kHertzDeepest * dx);
  const HertzFit fit = fit_hertz(curve, kHertzShallowest * dx, kHertzDeepest * dx);
  const double hertz = hertz_prefactor(scene);
  CaseResult result;
  result.resolution =
      "dx = 1 cm, h = 2 dx, sphere R = 12.5 dx, block 33 x 33 x 16 particles, fit over d = 0.5 to 2.5 dx";
  result.checks.push_back(absolute_check("exponent of F(d)", "-", 1.5, fit.exponent, 0.15));
  result.checks.push_back(relative_check("prefactor C of F = C d^1.5", "N/m^1.5", hertz, fit.prefactor, 0.25));
  if (!(fit.min_force > 0.0)) {
    result.checks.back().status = Status::fail;
    result.checks.back().note = "no contact force somewhere in the fitted range";
  }
  for (Check& c : result.checks) c.backend = "reference";
  std::vector<double> expected;
  for (double d : curve.depth) expected.push_back(d > 0.0 ? hertz * std::pow(d, 1.5) : 0.0);
  result.series.push_back({"force_depth",
                           "indentation d [m]",
                           curve.depth,
                           {{"measured F [N]", curve.force}, {"Hertz 4/3 E* sqrt(R) d^1.5 [N]", expected}},
                           true});
  return result;
}

}  // namespace mssph::validation
