// `mssph run SCENE.json`: simulate a scene and log it to HDF5.
#include "backend_factory/backend_factory.hpp"
#include "commands.hpp"
#include "guarded.hpp"
#include "option_checks.hpp"
#include "run/output_path.hpp"
#include "run/scene_run.hpp"
#include "util/errors.hpp"

#include <iostream>
#include <utility>

namespace mssph::cli {

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SceneRunRequest>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene and write its HDF5 run log");
  cmd->add_option("scene", args->scene_path,
                  "Scene file (JSON; keys and units in configs/README.md); none with --restart")
      ->check(CLI::ExistingFile);
  cmd->add_option("--restart", args->restart,
                  "Continue the unfinished run whose log is LOG (<out>.partial, or <out>) from its latest checkpoint, "
                  "appending to it; the scene, backend and options come from the log");
  cmd->add_option("--checkpoint-interval", args->checkpoint_interval,
                  "Write a checkpoint into the log every SECONDS of wall-clock time, for --restart (SIGINT, SIGTERM "
                  "and SIGHUP write one anyway)")
      ->check(positive_finite_number());
  std::string built;
  for (const std::string& name : available_backends()) built += (built.empty() ? "" : ", ") + name;
  cmd->add_option("--backend", args->backend,
                  "reference (float64), cpu (float32 kernels on the host), cuda (GPU), or auto (the fastest "
                  "available); this build has: " +
                      built)
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--out", args->output,
                  "Output HDF5 file (default " + default_output_path("<scene>", "<backend>") +
                      "); missing directories are created; an existing file is refused without --force");
  cmd->add_flag("--force", args->force,
                "Replace existing output files (--out, its sidecar, --record-device): regular files only, never "
                "an input of the run, a device, directory or symbolic link");
  cmd->add_flag("--dry-run", args->dry_run,
                "Check everything, print particles per body, the memory estimate, the time-step bounds and the "
                "step count, and write nothing");
  cmd->add_option("--threads", args->threads,
                  "Host threads for the start-up checks and the reference and cpu backends (default: "
                  "$OMP_NUM_THREADS if set, else the CPUs this process may use less the 1-minute load average, at "
                  "least 1; give concurrent runs their share)")
      ->check(CLI::Range(1, 4096));
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
  cmd->add_flag("--phase-timing", args->phase_timing,
                "Log each step's phase times in /timing/phases (on a GPU, events between the phases: about 10 us "
                "per step on an H100, so off by default)");
  cmd->footer(
      "The run log: one HDF5 file per run. Root attributes record the version, git commit, backend,\n"
      "device, precision, threads, the scene (config: after --set; config_file: the file verbatim),\n"
      "seed, start time and status: \"running\" while the run lasts, then \"completed\", \"failed:\n"
      "<reason>\" or \"interrupted: <signal> ...\". The log is written to <file>.partial and renamed\n"
      "to <file> only when the run completed: <file> holds a whole completed log or nothing; a failed,\n"
      "interrupted or killed run leaves <file>.partial. Time series (with units) reach the disk every\n"
      "output/flush_interval seconds of wall time, so a killed run leaves a readable file. With\n"
      "output/snapshot_interval > 0, particle snapshots are written too, with an XDMF sidecar\n"
      "<file>.xdmf that ParaView opens. The summary line on stdout names the file. A run locks\n"
      "<file>.partial while it lasts (a second run for the same --out is refused); to read it\n"
      "meanwhile (h5py, h5dump), set HDF5_USE_FILE_LOCKING=FALSE in the reader's environment.\n"
      "\n"
      "--set PATH=VALUE: PATH is a JSON path into the scene, '/'-separated with or without a leading\n"
      "'/' (simulation/dt, bodies/block/young_modulus); its parent must exist. VALUE is read as JSON\n"
      "when it is valid JSON (5e4, true, [0,0,-9.81], '\"text\"'), otherwise as a plain string\n"
      "(strain=cauchy). Overrides apply in order, before the scene is validated.\n"
      "\n"
      "Progress goes to stderr every few seconds once a run has lasted a few seconds. SIGINT, SIGTERM\n"
      "or SIGHUP stops the run after the current step; its log is marked \"interrupted: <signal> ...\".\n"
      "A closed stdout (a pipe into `head`) does not make a completed run fail.\n"
      "\n"
      "Checkpoints: the log holds the run's whole state after a signal, and every --checkpoint-interval\n"
      "seconds when given (two slots, /checkpoint/a and /checkpoint/b, written in turn). `mssph run\n"
      "--restart <file>.partial` continues an interrupted, failed or killed run from its latest\n"
      "checkpoint in the same log: rows and snapshots after it are dropped, the run goes on with the\n"
      "scene (after --set), backend and options it started with, and ends as the uninterrupted run\n"
      "would have, bit for bit, on the same backend and machine (root attribute `restarts` lists each).\n"
      "\n"
      "Exit codes: 0 completed (or --dry-run); 1 other error (disk full or another I/O failure: the\n"
      "log is kept as <file>.partial, marked \"failed: ...\" where the disk allowed it; or a completed\n"
      "run whose --record-device file could not be written, which it says); 2 bad input\n"
      "(scene file, --set, --backend, --out, --record-device, a run too large for this machine): no\n"
      "output is written; 3 simulation failure (blow-up): <file>.partial is kept, marked \"failed:\n"
      "...\"; 130, 143, 129 interrupted by SIGINT, SIGTERM, SIGHUP: <file>.partial is kept, marked\n"
      "\"interrupted: ...\".");
  cmd->callback([args, cmd, &exit_code] {
    guarded(exit_code, [&] {
      if (args->scene_path.empty() && args->restart.empty()) {
        throw InputError("run: a scene file is required (or --restart LOG to continue an unfinished run)");
      }
      // An empty path (an unset shell variable, say) is a mistake, not a request for the default.
      const std::pair<const char*, const std::string*> paths[] = {{"--out", &args->output},
                                                                  {"--record-device", &args->record_device}};
      for (const auto& [option, path] : paths) {
        if (cmd->count(option) > 0 && path->empty()) {
          throw InputError(std::string(option) + ": expected a file name, got an empty one");
        }
      }
      return run_scene(*args).exit_code;
    });
  });
}

}  // namespace mssph::cli
