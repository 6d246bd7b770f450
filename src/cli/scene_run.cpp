#include "scene_run.hpp"

#include "backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "haptics/haptics_run.hpp"
#include "output_path.hpp"
#include "scene/scene_builder.hpp"
#include "sim/interrupt.hpp"
#include "sim/stability.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace mssph::cli {
namespace {

// The scene file as the user wrote it, recorded next to the parsed scene.
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void print_summary_line(const std::string& output, const RunSummary& summary, const BackendInfo& info) {
  std::printf("%s: %zu steps, %.3f s simulated in %.2f s wall on %s (%s)", output.c_str(), summary.steps,
              summary.simulated_time, summary.wall_seconds, info.name.c_str(), info.device.c_str());
  if (!summary.force_body.empty()) {
    std::printf(", peak interaction force on %s %.3f N", summary.force_body.c_str(), summary.peak_force);
  }
  if (summary.peak_rendered_force) std::printf(", peak rendered force %.3f N", *summary.peak_rendered_force);
  if (!summary.outside_valid_range.empty()) {
    std::printf(", compressed beyond the material model's valid range in %s of logged samples",
                summary.outside_valid_range.c_str());
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

std::string command_line_of(const SceneRunRequest& request) {
  std::string line = "mssph run " + request.scene_path + " --backend " + request.backend;
  if (!request.output.empty()) line += " --out " + request.output;
  for (const std::string& o : request.overrides) line += " --set " + o;
  if (!request.record_device.empty()) line += " --record-device " + request.record_device;
  return line;
}

SceneRunResult run_scene(const SceneRunRequest& request) {
  // Everything that can be wrong with the input is found before the log file exists.
  const Scene scene = load_scene(request.scene_path, request.overrides);
  const std::string scene_text = read_text(request.scene_path);
  const std::string backend_name = resolve_backend_name(request.backend);
  SceneRunResult result;
  result.output = request.output.empty() ? default_output_path(scene.name, backend_name) : request.output;
  check_output_path(result.output);
  if (!request.record_device.empty()) check_device_recording_request(scene, request.record_device);
  ParticleSetup setup = build_particles(scene);
  std::vector<std::string> warnings = stability_warnings(setup);
  for (std::string& w : haptic_warnings(scene, setup)) warnings.push_back(std::move(w));
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";

  if (!request.quiet) {
    std::cerr << "mssph: " << scene.name << ": " << setup.size() << " particles (";
    for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
      std::cerr << (b ? ", " : "") << setup.bodies[b].name << " " << setup.bodies[b].count;
    }
    std::cerr << "), " << scene.simulation.duration / scene.simulation.dt << " steps of " << scene.simulation.dt
              << " s on " << backend_name << "\n";
  }
  const ParticleSetup setup_for_log = setup;
  std::unique_ptr<Backend> backend = make_backend(backend_name, std::move(setup));
  result.backend = backend->info();

  RunMetadata metadata;
  metadata.version = build_info().version;
  metadata.git_commit = build_info().git_commit;
  metadata.backend = result.backend.name;
  metadata.device = result.backend.device;
  metadata.precision = result.backend.precision;
  metadata.scene_name = scene.name;
  metadata.config_path = scene.source_file;
  metadata.config_json = scene.document.dump(2);
  metadata.config_file = scene_text;
  metadata.seed = static_cast<long long>(scene.simulation.seed);
  metadata.command_line = command_line_of(request);
  // From here on an interrupt ends the run through the log (status "failed: interrupted ...")
  // rather than killing the process with the log still saying "running".
  install_interrupt_handlers();
  RunLog log(result.output, metadata);
  std::string joined_warnings;
  for (const std::string& w : warnings) joined_warnings += w + "\n";
  log.set_attribute("/", "warnings", joined_warnings);

  try {
    result.summary =
        run_simulation(scene, setup_for_log, *backend, log, RunOptions{request.quiet, request.record_device});
    print_summary_line(result.output, result.summary, result.backend);
    result.exit_code = kExitOk;
  } catch (const SimulationFailure& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << result.output << "\n";
    result.exit_code = kExitSimulationFailure;
    result.error = e.what();
  } catch (const RunInterrupted& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << result.output << "\n";
    result.exit_code = kExitOther;
    result.error = e.what();
  } catch (const std::exception& e) {
    // A failure before the step loop (setting up series, the haptic session) still ends the log
    // with its reason instead of leaving it "running" like a killed run.
    if (!log.finished()) log.finish_failed(e.what());
    throw;
  }
  return result;
}

}  // namespace mssph::cli
