// The kernels suite's haptic-scene case: tap, squeeze and stir, float32 against the reference,
// compared from the runs' HDF5 logs (README.md beside this file).
#include "framework/case_functions.hpp"
#include "haptic_scenes.hpp"

#include <filesystem>
#include <iostream>

namespace mssph::validation {

CaseResult run_haptic_scenes_case(const CaseContext& context) {
  CaseResult result;
  struct SceneCase {
    std::string name;
    double quick_duration;  // cut after the motion each is about, as tests/haptics/haptic_scenes_test.cpp
    double tolerance;
  };
  // 2 % for the rigid and deformable media, 5 % for the fluid: the sphere drops' bounds.
  const std::vector<SceneCase> scenes{{"tap", 0.75, 0.02}, {"squeeze", 0.8, 0.02}, {"stir", 1.0, 0.05}};
  const std::string spacing = context.quick ? "0.04" : "0.02";
  result.resolution =
      context.quick ? "dx = 4 cm, cut after the motion (0.75, 0.8, 1.0 s)" : "dx = 2 cm, the scenes' full durations";
  const std::string work_dir = context.work_dir + "/haptic_scenes";
  std::filesystem::create_directories(work_dir);
  for (const std::string& backend : context.fast_backends) {
    const std::string skip = why_backend_cannot_run(backend);
    for (const SceneCase& s : scenes) {
      const std::string prefix = backend + " " + s.name + " ";
      if (!skip.empty()) {
        result.checks.push_back(skipped_check(prefix + "force and path NRMS", skip));
        result.checks.back().backend = backend;
        continue;
      }
      std::cerr << "validate: haptic scene " << s.name << ", " << backend << " vs reference\n";
      std::vector<std::string> overrides{"simulation/particle_spacing=" + spacing};
      if (context.quick) overrides.push_back("simulation/duration=" + exact(s.quick_duration));
      const HapticAgreement a = haptic_scene_agreement(backend, s.name, overrides, work_dir, context.replace_logs);
      for (Check c : {bound_check(prefix + "proxy force NRMS", "-", a.force_error, s.tolerance),
                      bound_check(prefix + "proxy path NRMS", "-", a.path_error, s.tolerance)}) {
        c.backend = backend;
        result.checks.push_back(std::move(c));
      }
      result.series.push_back({backend + "_" + s.name + "_force",
                               "time [s]",
                               a.time,
                               {{"reference |F| [N]", a.force_reference}, {backend + " |F| [N]", a.force_candidate}}});
    }
  }
  return result;
}

}  // namespace mssph::validation
