// `mssph figure tss`: the paper's Figure 4 idea as one scene (configs/tap_squeeze_stir.json): one
// proxy driven by a scripted hand taps a rigid bone, squeezes a deformable organ and stirs fluid
// blood in a basin. An ordinary run; scripts/figures/tss.py draws and checks it from the log.
#include "figure_command.hpp"
#include "run/scene_run.hpp"
#include "run/script_outputs.hpp"
#include "util/errors.hpp"

#include <filesystem>

namespace mssph::cli {

int make_figure_tss(const FigureTssOptions& options) {
  SceneRunRequest request;
  request.scene_path = options.scene;
  request.backend = options.backend;
  request.overrides = options.overrides;
  request.quiet = options.quiet;
  request.force = options.force;
  request.output = (std::filesystem::path(options.out) / "tap_squeeze_stir.h5").string();
  check_script_outputs(options.out, {"tss.png", "tss.svg", "tss_checks.json"}, options.force);
  const SceneRunResult result = run_scene(request);
  if (result.exit_code != kExitOk) return result.exit_code;
  const auto arguments = [&](const std::string& folder) {
    return std::vector<std::string>{"--out", folder, result.output};
  };
  return run_python_script_into("figures/tss.py", arguments, options.out, options.force) == 0 ? kExitOk : kExitOther;
}

}  // namespace mssph::cli
