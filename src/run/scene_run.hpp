#pragma once
// One ordinary run of a scene file, as `mssph run` does it: load and validate the scene (with
// --set overrides), check the output path, build the particles, warn about stability, construct
// the backend, open the HDF5 run log, run to the end and mark the log. Every subcommand that runs
// scenes (run, figure, sweep, validate) goes through here, so each of their runs is a run log a
// user could have made with `mssph run`.
#include "backend/backend.hpp"
#include "simulation_run.hpp"

#include <string>
#include <vector>

namespace mssph::cli {

struct SceneRunRequest {
  std::string scene_path;
  std::vector<std::string> overrides;  // --set PATH=VALUE, in order
  std::string backend = "auto";
  std::string output;         // "" for the default path results/runs/<scene>_<backend>.h5
  std::string record_device;  // "" for none
  // --tag NAME=VALUE: attributes of the log's /tags group, e.g. a sweep point's parameter values.
  // VALUE is stored as a number when it is one, else as text.
  std::vector<std::string> tags;
  bool quiet = false;
  bool force = false;                // replace existing output files (regular files only, never an input)
  bool dry_run = false;              // print the plan (particles, memory, dt bounds, steps) and write nothing
  int threads = 0;                   // host threads of the OpenMP loops; 0 for default_thread_count()
  bool phase_timing = false;         // log each step's phase times (/timing/phases)
  double checkpoint_interval = 0.0;  // wall-clock seconds between checkpoints; 0 for none
  // Continue the unfinished run whose log is here (<out>.partial, or <out> naming it) from its
  // latest checkpoint: scene, backend and options come from the log, so scene_path, overrides,
  // output, record_device, tags, backend and phase_timing stay unset.
  std::string restart;
};

struct SceneRunResult {
  // kExitOk, kExitSimulationFailure, kExitOther (I/O failure), or 128 + the signal's number when
  // a signal interrupted the run (130 SIGINT, 143 SIGTERM, 129 SIGHUP).
  int exit_code = 0;
  // The run log: the requested path when the run completed, <path>.partial otherwise, "" when
  // nothing was written (a dry run, a run interrupted or failed before its log existed).
  std::string output;
  std::string error;  // why the run failed; "" when it completed
  BackendInfo backend;
  RunSummary summary;  // meaningful when exit_code == kExitOk
};

// The command line that reproduces a request, recorded in the log.
std::string command_line_of(const SceneRunRequest& request);

// The checks run_scene makes of the scene, --set, --tag and every output path before it builds
// anything: for a command that starts several runs, to refuse them all before the first starts.
// Throws InputError.
void check_scene_run(const SceneRunRequest& request);

// Bad input (scene, --set, --out, --record-device, trajectory, a run the machine cannot hold, a
// log that cannot be continued) throws InputError before any output exists or changes.
// A run that starts ends in its log's status and the returned exit code; the one-line summary and
// errors are printed as `mssph run` prints them.
SceneRunResult run_scene(const SceneRunRequest& request);

}  // namespace mssph::cli
