// mssph: multistate SPH haptics benchmark and validation harness.
#include "commands.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"
#include "util/threads.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string_view>

int main(int argc, char** argv) {
  // The commands that simulate for their results wait passively (util/threads.hpp); the timing
  // commands (bench, figure) keep the OpenMP runtime's default, so that their numbers compare
  // with the baselines measured with it.
  const std::string_view command = argc > 1 ? argv[1] : "";
  if (command == "run" || command == "sweep" || command == "validate") mssph::wait_passively_unless_told(argv);
  CLI::App app{"mssph " + mssph::build_info().version +
               ": multistate SPH (fluid, deformable, rigid) with a 6DoF haptic proxy."};
  app.require_subcommand(1);
  app.footer(
      "Run 'mssph run --help' for scenes, --set overrides, the HDF5 run log and its default path.\n"
      "\n"
      "Exit codes: 0 ok; 1 other error (disk full, I/O failure); 2 bad input (config, arguments,\n"
      "trajectory file, a run too large for this machine): no output is written;\n"
      "3 simulation failure (blow-up): the run log is kept as <file>.partial, marked \"failed: ...\";\n"
      "130, 143, 129: interrupted by SIGINT, SIGTERM, SIGHUP (the log kept as <file>.partial,\n"
      "marked \"interrupted: ...\").");
  app.set_version_flag("--version", mssph::build_info().version + " (" + mssph::build_info().git_commit + ")");
  int exit_code = mssph::kExitOk;
  mssph::cli::add_run_command(app, exit_code);
  mssph::cli::add_info_command(app, exit_code);
  std::string command_line;
  for (int k = 0; k < argc; ++k) command_line += (k ? " " : "") + std::string(argv[k]);
  mssph::cli::add_figure_command(app, exit_code, command_line);
  mssph::cli::add_bench_command(app, exit_code);
  mssph::cli::add_sweep_command(app, exit_code);
  mssph::cli::add_validate_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return mssph::kExitBadInput;
  }
  return exit_code;
}
