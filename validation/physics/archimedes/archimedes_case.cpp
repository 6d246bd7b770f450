// Physics case: Archimedes floating depth for two sphere densities (README.md beside this file).
#include "framework/case_functions.hpp"
#include "physics/fluids.hpp"

namespace mssph::validation {

CaseResult run_archimedes_case(const CaseContext& context) {
  CaseResult result;
  if (auto skipped = skipped_without_physics_backend(context, "floating depth")) return *skipped;
  // --quick: sphere radius 3 dx (kArchimedesQuickSpacing); full: 0.01 m, 10 dx.
  const double dx = context.quick ? kArchimedesQuickSpacing : 0.01;
  const Scene base = case_scene("physics/archimedes");
  for (const double density : {500.0, 700.0}) {
    std::vector<std::string> overrides = resolution_overrides(base, dx);
    overrides.push_back("bodies/ball/density=" + exact(density));
    const FloatingMeasurement m =
        measure_floating(context.physics_backend, case_scene("physics/archimedes", overrides));
    const std::string label = "density " + std::to_string(static_cast<int>(density)) + ": ";
    result.checks.push_back(relative_check(label + "depth below the surface", "m", m.expected_depth, m.depth, 0.10));
    result.checks.push_back(bound_check(label + "|v_z| at the end (settled)", "m/s", m.vertical_speed, 0.02));
    result.resolution = "dx = " + exact(dx) + " m, h = 2 dx, sphere radius " + exact(m.radius) + " m as sampled, " +
                        std::to_string(m.particles) + " particles";
    result.series.push_back({"depth_" + std::to_string(static_cast<int>(density)),
                             "time [s]",
                             m.time,
                             {{"measured depth [m]", m.depth_history},
                              {"Archimedes depth [m]", std::vector<double>(m.time.size(), m.expected_depth)}}});
  }
  for (Check& c : result.checks) c.backend = context.physics_backend;
  return result;
}

}  // namespace mssph::validation
