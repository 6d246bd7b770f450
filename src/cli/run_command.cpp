// `mssph run SCENE.json`: simulate a scene and log it to HDF5.
#include "backend_factory.hpp"
#include "commands.hpp"
#include "config/scene_loader.hpp"
#include "scene/scene_builder.hpp"
#include "sim/interrupt.hpp"
#include "sim/simulation_run.hpp"
#include "sim/stability.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace mssph::cli {
namespace {

struct RunArguments {
  std::string scene_path;
  std::string backend = "auto";
  std::string output;
  std::vector<std::string> overrides;
  bool quiet = false;
};

std::string command_line_of(const RunArguments& a) {
  std::string line = "mssph run " + a.scene_path + " --backend " + a.backend;
  if (!a.output.empty()) line += " --out " + a.output;
  for (const std::string& o : a.overrides) line += " --set " + o;
  return line;
}

int run(const RunArguments& args) {
  // Everything that can be wrong with the input is found before the log file exists.
  const Scene scene = load_scene(args.scene_path, args.overrides);
  const std::string backend_name = resolve_backend_name(args.backend);
  ParticleSetup setup = build_particles(scene);
  const std::vector<std::string> warnings = stability_warnings(setup);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";

  const std::string output =
      args.output.empty() ? "results/runs/" + scene.name + "_" + backend_name + ".h5" : args.output;
  if (!args.quiet) {
    std::cerr << "mssph: " << scene.name << ": " << setup.size() << " particles (";
    for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
      std::cerr << (b ? ", " : "") << setup.bodies[b].name << " " << setup.bodies[b].count;
    }
    std::cerr << "), " << scene.simulation.duration / scene.simulation.dt << " steps of " << scene.simulation.dt
              << " s on " << backend_name << "\n";
  }
  const ParticleSetup setup_for_log = setup;
  std::unique_ptr<Backend> backend = make_backend(backend_name, std::move(setup));
  const BackendInfo info = backend->info();

  RunMetadata metadata;
  metadata.version = build_info().version;
  metadata.git_commit = build_info().git_commit;
  metadata.backend = info.name;
  metadata.device = info.device;
  metadata.precision = info.precision;
  metadata.scene_name = scene.name;
  metadata.config_path = scene.source_file;
  metadata.config_json = scene.document.dump(2);
  metadata.seed = static_cast<long long>(scene.simulation.seed);
  metadata.command_line = command_line_of(args);
  RunLog log(output, metadata);
  std::string joined_warnings;
  for (const std::string& w : warnings) joined_warnings += w + "\n";
  log.set_attribute("/", "warnings", joined_warnings);

  install_interrupt_handlers();
  try {
    const RunSummary summary = run_simulation(scene, setup_for_log, *backend, log, RunOptions{args.quiet});
    std::printf("%s: %zu steps, %.3f s simulated in %.2f s wall on %s (%s)", output.c_str(), summary.steps,
                summary.simulated_time, summary.wall_seconds, info.name.c_str(), info.device.c_str());
    if (!summary.force_body.empty()) {
      std::printf(", peak interaction force on %s %.3f N", summary.force_body.c_str(), summary.peak_force);
    }
    std::printf("\n");
    return kExitOk;
  } catch (const SimulationFailure& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << output << "\n";
    return kExitSimulationFailure;
  } catch (const RunInterrupted& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << output << "\n";
    return kExitOther;
  }
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene and write its HDF5 run log");
  cmd->add_option("scene", args->scene_path, "Scene file (JSON; keys and units in configs/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--backend", args->backend, "reference (float64), cpu (float32 kernels on the host), cuda, or auto")
      ->check(CLI::IsMember({"reference", "cpu", "cuda", "auto"}))
      ->capture_default_str();
  cmd->add_option("--out", args->output, "Output HDF5 file (default results/runs/<scene>_<backend>.h5)");
  cmd->add_option("--set", args->overrides,
                  "Override a scene value by JSON path, e.g. --set bodies/block/young_modulus=5e4 (repeatable)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or start-up lines (warnings and errors still print)");
  cmd->callback([args, &exit_code] {
    try {
      exit_code = run(*args);
    } catch (const InputError& e) {
      std::cerr << "error: " << e.what() << "\n";
      exit_code = kExitBadInput;
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      exit_code = kExitOther;
    }
  });
}

}  // namespace mssph::cli
