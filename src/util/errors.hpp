#pragma once
// The three kinds of failure a run can end in, each with its process exit code (see `mssph --help`).
#include <stdexcept>
#include <string>
#include <utility>

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
  explicit InputError(const std::string& message, std::string json_pointer = "")
      : std::runtime_error(message), json_pointer_(std::move(json_pointer)) {}
  // The JSON pointer of the offending scene value, e.g. "/simulation/dt"; "" when not a value.
  const std::string& json_pointer() const { return json_pointer_; }

 private:
  std::string json_pointer_;
};

// The simulation left its domain of validity (NaN, runaway speed). The run log is kept and
// marked failed.
class SimulationFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mssph
