// mssph: multistate SPH haptics benchmark and validation harness.
#include "commands.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"mssph " + mssph::build_info().version +
               ": multistate SPH (fluid, deformable, rigid) with a 6DoF haptic proxy."};
  app.require_subcommand(1);
  app.footer(
      "Run 'mssph run --help' for scenes, --set overrides, the HDF5 run log and its default path.\n"
      "\n"
      "Exit codes: 0 ok; 1 other error (an interrupted run, I/O failure); 2 bad input (config,\n"
      "arguments, trajectory file): no output is written; 3 simulation failure (blow-up): the run\n"
      "log is kept, marked \"failed: ...\".");
  app.set_version_flag("--version", mssph::build_info().version + " (" + mssph::build_info().git_commit + ")");
  int exit_code = mssph::kExitOk;
  mssph::cli::add_run_command(app, exit_code);
  mssph::cli::add_info_command(app, exit_code);
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
