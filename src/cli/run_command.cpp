// `mssph run SCENE.json`: simulate a scene and log it to HDF5.
#include "backend_factory.hpp"
#include "commands.hpp"
#include "config/scene_loader.hpp"
#include "haptics/haptics_run.hpp"
#include "output_path.hpp"
#include "scene/scene_builder.hpp"
#include "sim/interrupt.hpp"
#include "sim/simulation_run.hpp"
#include "sim/stability.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace mssph::cli {
namespace {

struct RunArguments {
  std::string scene_path;
  std::string backend = "auto";
  std::string output;
  std::vector<std::string> overrides;
  bool quiet = false;
  std::string record_device;
};

std::string command_line_of(const RunArguments& a) {
  std::string line = "mssph run " + a.scene_path + " --backend " + a.backend;
  if (!a.output.empty()) line += " --out " + a.output;
  for (const std::string& o : a.overrides) line += " --set " + o;
  if (!a.record_device.empty()) line += " --record-device " + a.record_device;
  return line;
}

// The scene file as the user wrote it, recorded next to the parsed scene.
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int run(const RunArguments& args) {
  // Everything that can be wrong with the input is found before the log file exists.
  const Scene scene = load_scene(args.scene_path, args.overrides);
  const std::string scene_text = read_text(args.scene_path);
  const std::string backend_name = resolve_backend_name(args.backend);
  const std::string output = args.output.empty() ? default_output_path(scene.name, backend_name) : args.output;
  check_output_path(output);
  if (!args.record_device.empty()) check_device_recording_request(scene, args.record_device);
  ParticleSetup setup = build_particles(scene);
  std::vector<std::string> warnings = stability_warnings(setup);
  for (std::string& w : haptic_warnings(scene, setup)) warnings.push_back(std::move(w));
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";

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
  metadata.config_file = scene_text;
  metadata.seed = static_cast<long long>(scene.simulation.seed);
  metadata.command_line = command_line_of(args);
  // From here on an interrupt ends the run through the log (status "failed: interrupted ...")
  // rather than killing the process with the log still saying "running".
  install_interrupt_handlers();
  RunLog log(output, metadata);
  std::string joined_warnings;
  for (const std::string& w : warnings) joined_warnings += w + "\n";
  log.set_attribute("/", "warnings", joined_warnings);

  try {
    const RunSummary summary =
        run_simulation(scene, setup_for_log, *backend, log, RunOptions{args.quiet, args.record_device});
    std::printf("%s: %zu steps, %.3f s simulated in %.2f s wall on %s (%s)", output.c_str(), summary.steps,
                summary.simulated_time, summary.wall_seconds, info.name.c_str(), info.device.c_str());
    if (!summary.force_body.empty()) {
      std::printf(", peak interaction force on %s %.3f N", summary.force_body.c_str(), summary.peak_force);
    }
    if (summary.peak_rendered_force) std::printf(", peak rendered force %.3f N", *summary.peak_rendered_force);
    std::printf("\n");
    return kExitOk;
  } catch (const SimulationFailure& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << output << "\n";
    return kExitSimulationFailure;
  } catch (const RunInterrupted& e) {
    std::cerr << "error: " << e.what() << "\n  the log is kept, marked failed: " << output << "\n";
    return kExitOther;
  } catch (const std::exception& e) {
    // A failure before the step loop (setting up series, the haptic session) still ends the log
    // with its reason instead of leaving it "running" like a killed run.
    if (!log.finished()) log.finish_failed(e.what());
    throw;
  }
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene and write its HDF5 run log");
  cmd->add_option("scene", args->scene_path, "Scene file (JSON; keys and units in configs/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  std::string built;
  for (const std::string& name : available_backends()) built += (built.empty() ? "" : ", ") + name;
  cmd->add_option("--backend", args->backend,
                  "reference (float64), cpu (float32 kernels on the host), cuda (GPU), or auto (the fastest "
                  "available); this build has: " + built)
      ->check(CLI::IsMember({"reference", "cpu", "cuda", "auto"}))
      ->capture_default_str();
  cmd->add_option("--out", args->output,
                   "Output HDF5 file (default " + default_output_path("<scene>", "<backend>") +
                       "); missing directories are created, an existing file is replaced");
  // One PATH=VALUE per --set, so that `--set a=1 scene.json` leaves the scene file positional.
  cmd->add_option("--set", args->overrides,
                  "Override a scene value: --set PATH=VALUE, e.g. --set bodies/block/young_modulus=5e4 "
                  "(repeatable; see below)")
      ->allow_extra_args(false);
  cmd->add_option("--record-device", args->record_device,
                  "Write the haptic device's trajectory (one pose per haptic tick) to FILE, .csv or .h5, in the "
                  "format a \"recorded\" trajectory replays");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or start-up lines (warnings and errors still print)");
  cmd->footer(
      "The run log: one HDF5 file per run. Root attributes record the version, git commit, backend,\n"
      "device, precision, the scene (config: after --set; config_file: the file verbatim), seed, start\n"
      "time and status: \"running\" while the run lasts, then \"completed\" or \"failed: <reason>\". Time\n"
      "series (with units) reach the disk every output/flush_interval seconds of wall time, so a\n"
      "killed run leaves a readable file. With output/snapshot_interval > 0, particle snapshots are\n"
      "written too, with an XDMF sidecar <file>.xdmf that ParaView opens. The summary line on stdout\n"
      "names the file. HDF5 locks the file while the run lasts: to read it meanwhile (h5py, h5dump),\n"
      "set HDF5_USE_FILE_LOCKING=FALSE in the reader's environment.\n"
      "\n"
      "--set PATH=VALUE: PATH is a JSON path into the scene, '/'-separated with or without a leading\n"
      "'/' (simulation/dt, bodies/block/young_modulus); its parent must exist. VALUE is read as JSON\n"
      "when it is valid JSON (5e4, true, [0,0,-9.81], '\"text\"'), otherwise as a plain string\n"
      "(strain=cauchy). Overrides apply in order, before the scene is validated.\n"
      "\n"
      "Progress goes to stderr every few seconds once a run has lasted a few seconds. SIGINT or\n"
      "SIGTERM stops the run after the current step; its log is marked \"failed: interrupted ...\".\n"
      "\n"
      "Exit codes: 0 completed; 1 other error (interrupted, I/O failure); 2 bad input (scene file,\n"
      "--set, --backend, --out): no output is written; 3 simulation failure (blow-up): the log is\n"
      "kept, marked \"failed: ...\".");
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
