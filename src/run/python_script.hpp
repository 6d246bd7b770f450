#pragma once
// The Python half of the CLI: plots and reports are Python scripts (h5py, NumPy, matplotlib with
// the Agg backend) under scripts/ that read only HDF5 and JSON files, so users can run and restyle
// them on their own. The CLI runs them with Debian's python3 (the one that sees python3-h5py), as
// the tests do.
#include <string>
#include <vector>

namespace mssph::cli {

// The interpreter: $MSSPH_PYTHON if set, else the one found at configure time.
std::string python_interpreter();

// The absolute path of a script given relative to the source tree's scripts/ folder
// (e.g. "figures/figure3.py"); $MSSPH_SCRIPTS_DIR overrides the folder.
std::string python_script_path(const std::string& relative);

// The modules the scripts import: the figures, the validation report and `sweep plot` need all
// three; a sweep's metrics and summary need the first two.
inline const std::vector<std::string> kPlottingModules{"h5py", "numpy", "matplotlib"};
inline const std::vector<std::string> kDataModules{"h5py", "numpy"};

// Throws std::runtime_error unless the interpreter runs Python 3 and imports every one of
// `modules`: a command that ends in a script checks this before its runs, so a machine without
// them fails at once, not after hours of simulation.
void check_python_modules(const std::vector<std::string>& modules);

// Runs the script with the arguments, its stdout and stderr passed through, and returns its exit
// code (127 when the interpreter could not be started, 128 + N when killed by signal N).
int run_python_script(const std::string& relative, const std::vector<std::string>& arguments);

// As run_python_script, but the script's stdout is returned in `output` instead of printed.
int run_python_script_capturing(const std::string& relative, const std::vector<std::string>& arguments,
                                std::string& output);

}  // namespace mssph::cli
