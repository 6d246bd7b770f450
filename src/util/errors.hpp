#pragma once
// The three kinds of failure a run can end in, each with its process exit code (see `mssph --help`).
#include <stdexcept>
#include <string>

namespace mssph {

enum ExitCode : int {
  kExitOk = 0,
  kExitOther = 1,
  kExitBadInput = 2,          // config, arguments, trajectory file
  kExitSimulationFailure = 3  // blow-up: NaN or a speed beyond the scene's bound
};

// Bad input from the user: the message names the file, the JSON path or row, and what was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The simulation left its domain of validity (NaN, runaway speed). The run log is kept and
// marked failed.
class SimulationFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mssph
