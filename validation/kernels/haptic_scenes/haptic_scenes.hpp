#pragma once
// The haptic scenes (configs/tap.json, squeeze.json, stir.json) run as `mssph run` runs them, on
// the reference and on a float32 backend; the proxy's interaction force and path are read back
// from the two run logs (/haptics/interaction/force, /haptics/proxy/position) and compared.
#include <string>
#include <vector>

namespace mssph::validation {

struct HapticAgreement {
  double force_error = 0.0;  // NRMS over the reference's peak interaction force
  double path_error = 0.0;   // NRMS of the displacement over the farthest the reference proxy travels
  std::vector<double> time, force_reference, force_candidate;  // per haptic tick; |F| [N]
};

// Runs configs/<scene>.json with the overrides on both backends, logs under `work_dir`
// (replacing earlier ones when `replace`).
HapticAgreement haptic_scene_agreement(const std::string& backend, const std::string& scene,
                                       const std::vector<std::string>& overrides, const std::string& work_dir,
                                       bool replace);

}  // namespace mssph::validation
