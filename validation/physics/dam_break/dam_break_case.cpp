// Physics case: a collapsing water column's surge front and height against experiments
// (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/dam_break/dam_break.hpp"

namespace mssph::validation {

namespace {

std::string comparison_text(const SurgeComparison& c) {
  return "speed dZ/dT " + exact(c.speed) + " (experiment " + exact(c.expected_speed) + "), time offset " +
         exact(c.offset) + ", largest front deviation " + exact(c.largest_deviation) + " over " +
         std::to_string(c.compared_points) + " points";
}

}  // namespace

CaseResult run_dam_break_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "surge front")) return *skipped;
  // The column's width a = 14.6 cm in spacings and the kernel support h in spacings: --quick 20 at
  // h = 2 dx (for 2 CPU cores); full 20, 40 and 80 with h / dx growing as dx shrinks, 2, 2.5 and
  // 3 (Quinlan et al. 2006; README.md says why), and 80 at the default h = 2 dx, reported.
  struct Resolution {
    int spacings;
    double support;  // h / dx
    bool checked;
  };
  const std::vector<Resolution> resolutions =
      context.quick ? std::vector<Resolution>{{20, 2.0, true}}
                    : std::vector<Resolution>{{20, 2.0, true}, {40, 2.5, true}, {80, 3.0, true}, {80, 2.0, false}};
  const DamBreakExperiment& primary = martin_moyce_1952();
  const DamBreakExperiment& second = koshizuka_oka_1996();
  for (const Resolution& r : resolutions) {
    const double dx = kDamBreakColumnWidth / r.spacings;
    const Scene scene = dam_break_scene(dx, {"simulation/smoothing_length=" + exact(r.support * dx)});
    const DamBreakMeasurement m = measure_dam_break(context.physics_backend, scene, 0.002);
    const NondimensionalCollapse c = nondimensional(m);
    const std::string name = "a" + std::to_string(r.spacings) + "_h" + exact(r.support) + "dx";
    const std::string label = "a = " + std::to_string(r.spacings) + " dx, h = " + exact(r.support) + " dx: ";
    const SurgeComparison surge = compare_surge(c, primary);
    const double height_deviation = largest_height_deviation(c, primary);
    if (r.checked) {
      result.checks.push_back(
          relative_check(label + "surge speed dZ/dT, Z in [1.5, 3.5]", "-", surge.expected_speed, surge.speed, 0.10));
      result.checks.push_back(
          bound_check(label + "largest |Z / Z_exp - 1|, release times aligned", "-", surge.largest_deviation, 0.10));
      result.checks.push_back(bound_check(label + "largest |H / H_exp - 1| at the wall", "-", height_deviation, 0.10));
    }
    const SurgeComparison other = compare_surge(c, second);
    result.details += label + (r.checked ? "" : "(reported, not checked) ") + primary.source + ": " +
                      comparison_text(surge) + ", largest height deviation " + exact(height_deviation) + ". " +
                      second.source + " (not checked, README.md): " + comparison_text(other) + ". " +
                      std::to_string(m.particles) + " particles.\n";
    result.series.push_back({"front_" + name, "T = t sqrt(2 g / a)", c.T, {{"front Z = x / a", c.Z}}});
    result.series.push_back({"height_" + name, "tau = t sqrt(g / a)", c.tau, {{"height at the wall H / 2a", c.H}}});
  }
  for (const DamBreakExperiment* experiment : {&primary, &second})
    result.series.push_back({"front " + experiment->source,
                             "T = t sqrt(2 g / a)",
                             experiment->front_time,
                             {{"front Z = x / a", experiment->front}}});
  result.series.push_back({"height " + primary.source,
                           "tau = t sqrt(g / a)",
                           primary.height_time,
                           {{"height at the wall H / 2a", primary.height}}});
  result.resolution =
      context.quick ? "a = 20 dx (dx = 7.3 mm), h = 2 dx, slab a / 2 thick"
                    : "a = 20, 40 and 80 dx at h = 2, 2.5 and 3 dx (and 80 dx at 2 dx, reported), slab a / 2 thick";
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
