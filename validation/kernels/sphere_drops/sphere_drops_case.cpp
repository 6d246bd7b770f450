// The kernels suite's many-step case: each fast backend against the reference on the three
// sphere drops of paper Figure 3, 0.5 s.
#include "framework/case_functions.hpp"
#include "sphere_drops.hpp"

#include <iostream>

namespace mssph::validation {

CaseResult run_sphere_drops_case(const CaseContext& context) {
  // The unit test's spacing in --quick; twice as fine for a GPU.
  const double spacing = context.quick ? 0.04 : 0.02;
  const double duration = 0.5;
  CaseResult result;
  result.resolution = "dx = " + std::to_string(spacing) + " m, h = 2 dx, 0.5 s (configs/sphere_drop_*.json)";
  for (const std::string& backend : context.fast_backends) {
    const std::string skip = why_backend_cannot_run(backend);
    for (const std::string medium : {"rigid", "deformable", "fluid"}) {
      const std::string config = "sphere_drop_" + medium + ".json";
      const std::string prefix = backend + " " + medium + " drop ";
      if (!skip.empty()) {
        result.checks.push_back(skipped_check(prefix + "force and path NRMS", skip));
        result.checks.back().backend = backend;
        continue;
      }
      std::cerr << "validate: sphere drop, " << backend << " vs reference, " << medium << "\n";
      const ParticleSetup setup = shipped_scene(config, spacing, duration);
      std::size_t sphere = 0;
      while (setup.bodies[sphere].name != "sphere") ++sphere;
      const auto steps = static_cast<std::size_t>(std::llround(duration / setup.dt));
      const DropAgreement a = drop_agreement(backend, setup, sphere, steps);
      for (Check c : {bound_check(prefix + "force NRMS", "-", a.force_error, drop_tolerance(config)),
                      bound_check(prefix + "path NRMS", "-", a.path_error, drop_tolerance(config))}) {
        c.backend = backend;
        if (a.travel < 0.01) {
          c.status = Status::fail;
          c.note = "the sphere did not move: nothing was compared";
        }
        result.checks.push_back(std::move(c));
      }
      result.series.push_back({backend + "_" + medium + "_drop_force",
                               "time [s]",
                               a.time,
                               {{"reference F_z [N]", a.force_reference}, {backend + " F_z [N]", a.force_candidate}}});
    }
  }
  return result;
}

}  // namespace mssph::validation
