#pragma once
// The subcommands of the mssph command line. Each registers itself on the CLI11 app and returns
// the callback's exit code through the shared slot.
#include <CLI/CLI.hpp>

#include <string>

namespace mssph::cli {

void add_run_command(CLI::App& app, int& exit_code);
void add_info_command(CLI::App& app, int& exit_code);
// command_line: the whole invocation, recorded in the figures' HDF5 files.
void add_figure_command(CLI::App& app, int& exit_code, const std::string& command_line);
void add_bench_command(CLI::App& app, int& exit_code);
void add_sweep_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);  // validate_command.cpp

}  // namespace mssph::cli
