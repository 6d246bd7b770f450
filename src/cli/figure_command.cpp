// Registers `mssph figure 2`, `mssph figure 3` and `mssph figure tss` on the command line.
#include "figure_command.hpp"
#include "backend_factory/backend_factory.hpp"
#include "commands.hpp"
#include "guarded.hpp"
#include "util/errors.hpp"

#include <iostream>

namespace mssph::cli {
namespace {

const char* kBackendHelp = "reference, cpu, cuda or auto (cuda when a GPU is present, else cpu)";

void add_figure2(CLI::App& figure, int& exit_code, const std::string& command_line) {
  auto o = std::make_shared<Figure2Options>();
  CLI::App* cmd = figure.add_subcommand("2", "Paper Figure 2: time per step against particle count, per medium");
  cmd->add_option("--backend", o->backend, kBackendHelp)
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--media", o->media, "Media to time, comma-separated")
      ->delimiter(',')
      ->check(CLI::IsMember({"fluid", "deformable", "rigid"}))
      ->capture_default_str();
  cmd->add_option("--sizes", o->sizes, "Particle counts of the block, comma-separated (default: the paper's range)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--max", o->max_particles,
                  "Extend the sizes on a 1-2-5 log scale up to this many particles (e.g. 1000000 on a GPU)");
  cmd->add_option("--geometry", o->geometry,
                  "paper: 0.5 m square base, fixed 2 cm spacing, height from the particle count (section 5.1); "
                  "fixed-height: the 50 x 50 x 20 cm block, spacing from the particle count")
      ->check(CLI::IsMember({"paper", "fixed-height"}))
      ->capture_default_str();
  cmd->add_option("--min-time", o->min_seconds, "Seconds of timed steps per size, at least")->capture_default_str();
  cmd->add_flag("--force", o->force, "Replace the figure's earlier output files in --out (regular files only)");
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->footer(
      "Writes DIR/figure2.h5 (every timing with the machine: CPU, GPU, driver, commit, build type,\n"
      "backend, precision, date), DIR/figure2.csv, DIR/figure2.png and .svg (rigid dashed, deformable\n"
      "continuous, fluid dotted, as the paper draws them) and, when the sizes span more than a decade,\n"
      "DIR/figure2_loglog.png and .svg. Prints the fitted slopes (ms per 1,000 particles over the\n"
      "paper's 2,000-30,000) and their ratios next to the paper's, the update rates at 20,000 fluid and\n"
      "5,000 deformable particles, and above 100,000 particles the exponent of time against N.\n"
      "Only the step is timed: after a warm-up, batches of steps each closed by one synchronisation,\n"
      "the median per-step time with its min and max. Redraw with: python3 scripts/figures/figure2.py\n"
      "DIR/figure2.h5 --out DIR.");
  cmd->callback([o, &exit_code, command_line] { guarded(exit_code, [&] { return make_figure2(*o, command_line); }); });
}

// The shipped scenes, wherever mssph is run from.
const std::string kShippedConfigs = MSSPH_SOURCE_DIR "/configs";

void add_figure3(CLI::App& figure, int& exit_code) {
  auto o = std::make_shared<Figure3Options>();
  o->configs = kShippedConfigs;
  CLI::App* cmd = figure.add_subcommand("3", "Paper Figure 3: force on a sphere dropped on rigid, deformable, fluid");
  cmd->add_option("--backend", o->backend, kBackendHelp)
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--resolution", o->resolution,
                  "coarse (4 cm spacing: minutes on 2 CPU cores), paper (2 cm, the shipped scenes), fine (1 cm, GPU)")
      ->check(CLI::IsMember({"coarse", "paper", "fine"}))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_option("--configs", o->configs, "Folder with sphere_drop_{rigid,deformable,fluid}.json")
      ->capture_default_str();
  cmd->add_option("--set", o->overrides, "Override a scene value in all three runs: --set PATH=VALUE (as mssph run)")
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress lines from the runs");
  cmd->add_flag("--force", o->force, "Replace the figure's earlier output files in --out (regular files only)");
  cmd->footer(
      "Runs configs/sphere_drop_{rigid,deformable,fluid}.json, each an ordinary run with its log in\n"
      "DIR/sphere_drop_<medium>.h5, then draws DIR/figure3.png and .svg (interaction force on the\n"
      "sphere, vertical and magnitude; the force the device renders) and checks each curve against\n"
      "physics, printing measured, expected, tolerance and PASS/FAIL, written to\n"
      "DIR/figure3_checks.json. Redraw or re-check with: python3 scripts/figures/figure3.py --out DIR\n"
      "DIR/sphere_drop_*.h5.\n"
      "\n"
      "Exit codes: 0 all checks pass; 1 a check failed, a run did not complete, or Python lacks\n"
      "h5py, NumPy or matplotlib (checked before the runs); 2 bad input; 3 a run blew up.");
  cmd->callback([o, &exit_code] { guarded(exit_code, [&] { return make_figure3(*o); }); });
}

void add_figure_tss(CLI::App& figure, int& exit_code) {
  auto o = std::make_shared<FigureTssOptions>();
  o->scene = kShippedConfigs + "/tap_squeeze_stir.json";
  CLI::App* cmd =
      figure.add_subcommand("tss", "One world, three states: tap a bone, squeeze an organ, stir blood, with one proxy");
  cmd->add_option("--backend", o->backend, kBackendHelp)
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--scene", o->scene, "The scene")->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_option("--set", o->overrides, "Override a scene value: --set PATH=VALUE (as mssph run)")
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress lines from the run");
  cmd->add_flag("--force", o->force, "Replace the figure's earlier output files in --out (regular files only)");
  cmd->footer(
      "Runs the scene into DIR/tap_squeeze_stir.h5 and draws DIR/tss.png and .svg: the rendered force\n"
      "and torque against time, the tap, squeeze and stir phases shaded. Checks that in each phase the\n"
      "force comes from the body touched (by the change of each body's interaction force) and reports\n"
      "the device's saturation, written to DIR/tss_checks.json.\n"
      "\n"
      "Exit codes: 0 all checks pass; 1 a check failed, the run did not complete, or Python lacks\n"
      "h5py, NumPy or matplotlib (checked before the run); 2 bad input; 3 the run blew up.");
  cmd->callback([o, &exit_code] { guarded(exit_code, [&] { return make_figure_tss(*o); }); });
}

}  // namespace

void add_figure_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  CLI::App* figure =
      app.add_subcommand("figure", "Reproduce the paper's figures: 2 (step time), 3 (sphere drops), tss");
  figure->require_subcommand(1);
  add_figure2(*figure, exit_code, command_line);
  add_figure3(*figure, exit_code);
  add_figure_tss(*figure, exit_code);
}

}  // namespace mssph::cli
