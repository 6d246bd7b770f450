#include "haptic_scenes.hpp"

#include "framework/fits.hpp"
#include "framework/run_log_reader.hpp"
#include "run/scene_run.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <stdexcept>

namespace mssph::validation {

HapticAgreement haptic_scene_agreement(const std::string& backend, const std::string& scene,
                                       const std::vector<std::string>& overrides, const std::string& work_dir,
                                       bool replace) {
  const auto run = [&](const std::string& name) {
    cli::SceneRunRequest request;
    request.scene_path = std::string(MSSPH_SOURCE_DIR) + "/configs/" + scene + ".json";
    request.overrides = overrides;
    request.backend = name;
    request.output = work_dir + "/" + scene + "_" + name + ".h5";
    request.quiet = true;
    request.force = replace;
    const cli::SceneRunResult result = cli::run_scene(request);
    if (result.exit_code != kExitOk) throw std::runtime_error(request.output + ": the run failed: " + result.error);
    return result.output;
  };
  const std::string reference_log = run("reference");
  const std::string candidate_log = run(backend);
  const auto force_ref = read_vectors(reference_log, "/haptics/interaction/force");
  const auto force_got = read_vectors(candidate_log, "/haptics/interaction/force");
  const auto path_ref = read_vectors(reference_log, "/haptics/proxy/position");
  const auto path_got = read_vectors(candidate_log, "/haptics/proxy/position");
  if (force_ref.size() != force_got.size() || path_ref.size() != path_got.size() || path_ref.empty()) {
    throw std::runtime_error(reference_log + " and " + candidate_log + " have different numbers of haptic ticks");
  }
  HapticAgreement a;
  a.force_error = normalised_rms(force_got, force_ref);
  std::vector<Eigen::Vector3d> displacement_ref, displacement_got;
  for (std::size_t k = 0; k < path_ref.size(); ++k) {
    displacement_ref.push_back(path_ref[k] - path_ref.front());
    displacement_got.push_back(path_got[k] - path_ref.front());
  }
  a.path_error = normalised_rms(displacement_got, displacement_ref);
  a.time = read_series(reference_log, "/haptics/time");
  for (std::size_t k = 0; k < force_ref.size(); ++k) {
    a.force_reference.push_back(force_ref[k].norm());
    a.force_candidate.push_back(force_got[k].norm());
  }
  return a;
}

}  // namespace mssph::validation
