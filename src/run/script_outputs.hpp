#pragma once
// The files a plotting script draws (python_script.hpp) follow the rules of every output of mssph
// (io/output_claim.hpp): the script writes into a fresh folder of its own inside the output
// folder, and each file it wrote is then moved to the output folder without replacing anything,
// or, with --force, replacing only a regular file that no run holds locked.
#include <functional>
#include <string>
#include <vector>

namespace mssph::cli {

// The checks before a command starts the work whose files a script will draw into `out`: throws
// InputError "--out <out>/<name>: ..." when one of `names` may not be written (check_output_file),
// and std::runtime_error when the script could not run (check_python_modules, kPlottingModules).
void check_script_outputs(const std::string& out, const std::vector<std::string>& names, bool replace);

// Runs `relative` with the arguments `arguments` makes for the folder it is to write into, then
// moves what it wrote into `out` (which must exist) and says so on stdout; `replace` is --force.
// Returns the script's exit code. Throws std::runtime_error naming each file that could not be
// moved; those stay in the script's folder, which the message names.
int run_python_script_into(const std::string& relative,
                           const std::function<std::vector<std::string>(const std::string& folder)>& arguments,
                           const std::string& out, bool replace);

}  // namespace mssph::cli
