// `mssph run SCENE.json`: simulate a scene and log it to HDF5.
#include "backend_factory.hpp"
#include "commands.hpp"
#include "output_path.hpp"
#include "scene_run.hpp"
#include "util/errors.hpp"

#include <iostream>

namespace mssph::cli {

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SceneRunRequest>();
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
  cmd->add_option("--tag", args->tags,
                  "Record NAME=VALUE as an attribute of the log's /tags group (repeatable; a number is stored as a "
                  "number); mssph sweep tags each point's log with its parameters")
      ->allow_extra_args(false);
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
      exit_code = run_scene(*args).exit_code;
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
