// `mssph figure 3`: the paper's Figure 3 (Cirio et al. 2011): a 20 cm radius sphere coupled to the
// simulated Virtuose, dropped on a 50 x 50 x 20 cm rigid, deformable and fluid block. Each drop is
// an ordinary run with its own HDF5 log; scripts/figures/figure3.py draws the three force curves
// on one graph and checks their shapes against physics.
#include "config/scene_loader.hpp"
#include "figure_command.hpp"
#include "run/scene_run.hpp"
#include "run/script_outputs.hpp"
#include "util/errors.hpp"

#include <cstdio>
#include <filesystem>
#include <map>

namespace mssph::cli {
namespace {

namespace fs = std::filesystem;

// Particle spacing of each resolution [m]: the shipped scenes are the paper's 2 cm.
double spacing_of(const std::string& resolution) {
  static const std::map<std::string, double> spacings{{"coarse", 0.04}, {"paper", 0.02}, {"fine", 0.01}};
  const auto it = spacings.find(resolution);
  if (it == spacings.end()) throw InputError("--resolution " + resolution + ": expected coarse, paper or fine");
  return it->second;
}

// Simulated time each drop needs for its checks [s], which read the last 0.5 s: the rigid sphere's
// impact and first bounces are over within 1.5 s (the shipped duration); the floating sphere's
// bobbing has died out by 3 s, the bounces on the deformable block (its viscous modulus) by 4 s
// at 4, 2 and 1 cm.
double duration_of(const std::string& medium) {
  if (medium == "rigid") return 1.5;
  return medium == "fluid" ? 3.0 : 4.0;
}

// The shipped scenes' dt holds at the paper's 2 cm. Below it, the deformable block's viscous
// stress, an explicit diffusion with the bound 0.05 h^2 rho0 / ((eta / E)(lambda + 2 mu))
// (docs/model.md), needs the step shrunk with dx^2; the other drops keep theirs.
constexpr double kPaperSpacing = 0.02;  // [m]

std::vector<std::string> step_override(const std::string& medium, const std::string& path, double spacing) {
  if (medium != "deformable" || spacing >= kPaperSpacing) return {};
  const double scale = (spacing / kPaperSpacing) * (spacing / kPaperSpacing);
  char dt[40];
  std::snprintf(dt, sizeof dt, "simulation/dt=%.17g", load_scene(path).simulation.dt * scale);
  return {dt};
}

std::string scene_path(const Figure3Options& options, const std::string& medium) {
  const fs::path path = fs::path(options.configs) / ("sphere_drop_" + medium + ".json");
  if (!fs::is_regular_file(path)) {
    throw InputError("--configs " + options.configs + ": no " + path.filename().string() + " there");
  }
  return path.string();
}

}  // namespace

int make_figure3(const Figure3Options& options) {
  const double spacing = spacing_of(options.resolution);
  const std::vector<std::string> media{"rigid", "deformable", "fluid"};
  std::vector<SceneRunRequest> requests;
  for (const std::string& medium : media) {
    SceneRunRequest r;
    r.scene_path = scene_path(options, medium);
    r.backend = options.backend;
    r.quiet = options.quiet;
    r.force = options.force;
    r.output = (fs::path(options.out) / ("sphere_drop_" + medium + ".h5")).string();
    r.overrides = {"simulation/particle_spacing=" + std::to_string(spacing),
                   "simulation/duration=" + std::to_string(duration_of(medium))};
    for (const std::string& step : step_override(medium, r.scene_path, spacing)) r.overrides.push_back(step);
    // The fluid's free surface is measured from the particles at the end of the run.
    if (medium == "fluid") r.overrides.push_back("output/snapshot_interval=0.5");
    // The user's overrides come last, so they win.
    r.overrides.insert(r.overrides.end(), options.overrides.begin(), options.overrides.end());
    requests.push_back(std::move(r));
  }
  // Every scene is loaded with its overrides, and every output checked as its run will check it,
  // before the first run starts: a bad --set or an earlier figure in the way fails at once.
  for (const SceneRunRequest& r : requests) check_scene_run(r);
  check_script_outputs(options.out, {"figure3.png", "figure3.svg", "figure3_checks.json"}, options.force);
  for (std::size_t m = 0; m < requests.size(); ++m) {
    std::fprintf(stderr, "figure 3: run %zu of 3, %s block at %s resolution (%.0f cm)\n", m + 1, media[m].c_str(),
                 options.resolution.c_str(), 100.0 * spacing);
    const SceneRunResult result = run_scene(requests[m]);
    if (result.exit_code != kExitOk) {
      std::fprintf(stderr, "figure 3: the %s drop did not complete (%s); no figure drawn\n", media[m].c_str(),
                   result.error.c_str());
      return result.exit_code;
    }
  }
  const auto arguments = [&](const std::string& folder) {
    std::vector<std::string> list{"--out", folder, "--resolution", options.resolution};
    for (const SceneRunRequest& r : requests) list.push_back(r.output);
    return list;
  };
  return run_python_script_into("figures/figure3.py", arguments, options.out, options.force) == 0 ? kExitOk
                                                                                                  : kExitOther;
}

}  // namespace mssph::cli
