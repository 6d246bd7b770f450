#pragma once
// One ordinary run of a scene file, as `mssph run` does it: load and validate the scene (with
// --set overrides), check the output path, build the particles, warn about stability, construct
// the backend, open the HDF5 run log, run to the end and mark the log. Every subcommand that runs
// scenes (run, figure, sweep, validate) goes through here, so each of their runs is a run log a
// user could have made with `mssph run`.
#include "sim/backend.hpp"
#include "sim/simulation_run.hpp"

#include <string>
#include <vector>

namespace mssph::cli {

struct SceneRunRequest {
  std::string scene_path;
  std::vector<std::string> overrides;  // --set PATH=VALUE, in order
  std::string backend = "auto";
  std::string output;                  // "" for the default path results/runs/<scene>_<backend>.h5
  std::string record_device;           // "" for none
  // --tag NAME=VALUE: attributes of the log's /tags group, e.g. a sweep point's parameter values.
  // VALUE is stored as a number when it is one, else as text.
  std::vector<std::string> tags;
  bool quiet = false;
};

struct SceneRunResult {
  int exit_code = 0;        // kExitOk, kExitSimulationFailure or kExitOther (interrupted)
  std::string output;       // the run log's path
  std::string error;        // why the run failed; "" when it completed
  BackendInfo backend;
  RunSummary summary;       // meaningful when exit_code == kExitOk
};

// The command line that reproduces a request, recorded in the log.
std::string command_line_of(const SceneRunRequest& request);

// Bad input (scene, --set, --out, trajectory) throws InputError before any output exists.
// A run that starts ends in its log's status and the returned exit code; the one-line summary and
// errors are printed as `mssph run` prints them.
SceneRunResult run_scene(const SceneRunRequest& request);

}  // namespace mssph::cli
