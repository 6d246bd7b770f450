// `mssph sweep SWEEP.json`: run every point of a parameter sweep as an ordinary `mssph run`,
// locally (--jobs, --gpus), as one shard of several (--shard, Slurm arrays) or through Slurm
// (--emit-slurm); `mssph sweep merge DIR` and `mssph sweep plot DIR` summarise and plot.
#include "backend_factory/backend_factory.hpp"
#include "commands.hpp"
#include "guarded.hpp"
#include "option_checks.hpp"
#include "run/python_script.hpp"
#include "sweep/point_runner.hpp"
#include "sweep/point_status.hpp"
#include "sweep/shard.hpp"
#include "sweep/slurm_script.hpp"
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_points.hpp"
#include "util/errors.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace mssph::cli {
namespace {

namespace fs = std::filesystem;
using namespace mssph::sweep;

constexpr const char* kMetricsScript = "analysis/log_metrics.py";
constexpr const char* kSummaryScript = "sweep/summarize.py";
constexpr const char* kPlotScript = "sweep/plot.py";

struct SweepArgs {
  std::string sweep_file;
  std::string out;
  std::string backend = "auto";
  std::vector<std::string> overrides;
  std::size_t jobs = 1;
  std::string gpus;
  std::string shard;
  bool retry_failed = false;
  double checkpoint_interval = 0.0;  // passed to every point's run
  bool dry_run = false;
  bool emit_slurm = false;
  std::size_t shards = 0;
  std::size_t max_parallel = 0;
  std::string partition;
  int gpus_per_task = 0;
  int cpus_per_task = 0;
  std::string time_limit;
  std::vector<std::string> sbatch_options;
};

// The metric names scripts/analysis/log_metrics.py defines: the one list a sweep file's
// "metrics" is checked against.
std::vector<std::string> known_metrics() {
  std::string output;
  const int code = run_python_script_capturing(kMetricsScript, {"--list"}, output);
  if (code != 0) {
    throw std::runtime_error("cannot list the metrics: " + python_interpreter() + " " +
                             python_script_path(kMetricsScript) + " --list exited with code " + std::to_string(code));
  }
  std::vector<std::string> names;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) names.push_back(line);
  }
  // An interpreter that runs nothing (MSSPH_PYTHON=/bin/true) must not pass for a script that
  // defines no metric: the summary would silently have none.
  if (names.empty()) {
    throw std::runtime_error("cannot list the metrics: " + python_interpreter() + " " +
                             python_script_path(kMetricsScript) + " --list printed none");
  }
  return names;
}

// The program every point runs: this binary, or the test hook MSSPH_SWEEP_RUNNER, a program
// taking the same arguments (the tests use it to see what each point was started with).
std::string point_program() {
  if (const char* hook = std::getenv("MSSPH_SWEEP_RUNNER"); hook && *hook) return hook;
  return fs::read_symlink("/proc/self/exe").string();
}

std::vector<std::string> split_gpus(const std::string& text) {
  std::vector<std::string> gpus;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ',')) {
    if (item.empty() || item.find_first_of(" \t") != std::string::npos) {
      throw InputError("--gpus " + text + ": expected a comma-separated list of GPU indices, e.g. --gpus 0,1");
    }
    if (std::find(gpus.begin(), gpus.end(), item) != gpus.end()) {
      throw InputError("--gpus " + text + ": GPU " + item + " is listed twice");
    }
    gpus.push_back(item);
  }
  if (gpus.empty()) throw InputError("--gpus: expected at least one GPU index");
  return gpus;
}

// One slot per GPU (the child sees only its GPU), or --jobs host slots sharing the cores.
std::vector<RunSlot> make_slots(const SweepArgs& args) {
  std::vector<RunSlot> slots;
  if (!args.gpus.empty()) {
    for (const std::string& gpu : split_gpus(args.gpus))
      slots.push_back({"GPU " + gpu, {"CUDA_VISIBLE_DEVICES=" + gpu}});
    return slots;
  }
  std::vector<std::string> environment;
  // Host backends parallelise each run with OpenMP; several runs at once share the cores
  // instead of each starting a thread per core. An OMP_NUM_THREADS the user set is kept.
  if (args.jobs > 1 && !std::getenv("OMP_NUM_THREADS")) {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    environment.push_back("OMP_NUM_THREADS=" + std::to_string(std::max<std::size_t>(1, cores / args.jobs)));
  }
  for (std::size_t j = 0; j < args.jobs; ++j) slots.push_back({"job " + std::to_string(j + 1), environment});
  return slots;
}

void check_arguments(const SweepArgs& args) {
  if (!args.gpus.empty()) split_gpus(args.gpus);
  if (!args.gpus.empty() && args.jobs != 1) {
    throw InputError("--gpus and --jobs: give one; --gpus runs one point per listed GPU at a time");
  }
  if (!args.gpus.empty() && args.backend != "cuda" && args.backend != "auto") {
    throw InputError("--gpus needs --backend cuda (or auto), got --backend " + args.backend);
  }
  if (!args.emit_slurm && (args.shards || args.max_parallel || !args.partition.empty() || args.gpus_per_task ||
                           args.cpus_per_task || !args.time_limit.empty() || !args.sbatch_options.empty())) {
    throw InputError(
        "--shards, --max-parallel, --partition, --gpus-per-task, --cpus-per-task, --time and "
        "--sbatch-option only shape the scripts of --emit-slurm");
  }
  for (const std::string& text : {args.partition, args.time_limit}) {
    if (text.find_first_of("\n\r") != std::string::npos) throw InputError("Slurm options must be one line each");
  }
  for (const std::string& text : args.sbatch_options) {
    if (text.empty() || text.find_first_of("\n\r") != std::string::npos) {
      throw InputError("--sbatch-option: expected one non-empty line, e.g. --sbatch-option=--account=lab");
    }
  }
}

std::string default_directory(const SweepFile& sweep) { return "results/sweeps/" + sweep.name; }

std::string point_label(const SweepPoint& p, std::size_t total) {
  return "point " + std::to_string(p.index + 1) + "/" + std::to_string(total) + " (" + p.describe() + ")";
}

// `continuable`: the point's partial log holds a checkpoint, and the run continues from it with
// the scene, options and tags recorded there.
PointTask make_task(const SweepPoint& point, std::size_t total, const SweepFile& sweep, const SweepArgs& args,
                    const std::string& program, const std::string& directory, bool continuable) {
  const std::string folder = directory + "/" + kPointsFolder;
  PointTask task;
  task.label = point_label(point, total);
  task.log_path = folder + "/" + point.log_name();
  task.point_hash = point.hash;
  task.output_path = folder + "/point-" + point.hash + ".out";
  if (continuable) {
    task.argv = {program, "run", "--restart", task.log_path + ".partial"};
    if (args.checkpoint_interval > 0.0) {
      task.argv.insert(task.argv.end(), {"--checkpoint-interval", std::to_string(args.checkpoint_interval)});
    }
    return task;
  }
  // --force: a point runs only when it is not completed, and then replaces what an earlier try
  // left (a failed or interrupted run's <log>.partial).
  task.argv = {program,       "run",        fs::absolute(sweep.scene_path).lexically_normal().string(),
               "--backend",   args.backend, "--out",
               task.log_path, "--force"};
  for (const std::string& o : point.overrides) {
    task.argv.push_back("--set");
    task.argv.push_back(o);
  }
  task.argv.insert(task.argv.end(), {"--tag", "sweep=" + sweep.name, "--tag", "point=" + point.hash});
  if (args.checkpoint_interval > 0.0) {
    task.argv.insert(task.argv.end(), {"--checkpoint-interval", std::to_string(args.checkpoint_interval)});
  }
  for (const auto& [name, value] : point.parameters) {
    task.argv.push_back("--tag");
    task.argv.push_back(name + "=" + (value.is_string() ? value.get<std::string>() : value.dump()));
  }
  if (point.seed) task.argv.insert(task.argv.end(), {"--tag", "seed=" + std::to_string(*point.seed)});
  return task;
}

int emit_slurm(const SweepArgs& args, const SweepFile& sweep, const std::vector<SweepPoint>& points,
               const std::string& directory) {
  SlurmOptions o;
  o.program = fs::read_symlink("/proc/self/exe").string();
  o.sweep_file = fs::absolute(sweep.source_file).lexically_normal().string();
  o.directory = directory;
  o.sweep_name = sweep.name;
  o.backend = args.backend;
  o.overrides = args.overrides;
  o.retry_failed = args.retry_failed;
  // Slurm's default MaxArraySize is 1001: larger sweeps put several points in each task.
  o.tasks = args.shards ? std::min(args.shards, points.size()) : std::min<std::size_t>(points.size(), 1000);
  o.max_parallel = args.max_parallel;
  o.partition = args.partition;
  o.gpus_per_task = args.gpus_per_task;
  o.cpus_per_task = args.cpus_per_task;
  o.time_limit = args.time_limit;
  o.sbatch_options = args.sbatch_options;
  const SlurmScripts scripts = write_slurm_scripts(o);
  std::cout << "sweep " << sweep.name << ": " << points.size() << " points in " << o.tasks << " array tasks\n"
            << "  " << scripts.array_script << "\n  " << scripts.merge_script << "\n"
            << "submit both (the merge after the array) with:\n  bash " << scripts.submit_script << "\n";
  return kExitOk;
}

int print_dry_run(const SweepFile& sweep, const std::vector<SweepPoint>& points, const std::optional<Shard>& shard,
                  const std::string& directory) {
  std::cout << "sweep " << sweep.name << ": " << points.size() << " points of " << sweep.scene_path
            << ", every one accepted by the scene loader; logs would go to " << directory << "/" << kPointsFolder
            << "/\n";
  for (const SweepPoint& p : points) {
    if (shard && !shard->contains(p.index)) continue;
    const PointStatus status = read_point_status(directory + "/" + kPointsFolder + "/" + p.log_name(), p.hash);
    std::cout << "  " << p.index << "  " << p.log_name() << "  " << to_string(status.state) << "  " << p.describe()
              << "\n";
  }
  return kExitOk;
}

int run_sweep(const SweepArgs& args) {
  check_arguments(args);
  check_python_modules(kDataModules);  // the metrics and the summary are scripts that import them
  const SweepFile sweep = load_sweep_file(args.sweep_file, known_metrics());
  std::vector<SweepPoint> points = expand_points(sweep, args.overrides);
  validate_points(sweep, args.overrides, points);
  const std::string directory =
      fs::absolute(args.out.empty() ? default_directory(sweep) : args.out).lexically_normal().string();
  if (fs::exists(directory) && !fs::is_directory(directory))
    throw InputError("--out " + directory + ": not a directory");

  std::optional<Shard> shard =
      args.shard.empty() ? shard_from_slurm(slurm_array_environment()) : parse_shard(args.shard);
  if (args.dry_run) return print_dry_run(sweep, points, shard, directory);
  write_manifest(directory, make_manifest(sweep, points, {args.overrides, args.backend}));
  if (args.emit_slurm) return emit_slurm(args, sweep, points, directory);

  // What is left to do: resume skips completed points, and failed ones unless asked.
  std::vector<std::pair<const SweepPoint*, bool>> to_run;  // with whether it continues from a checkpoint
  SweepCounts counts;
  std::vector<std::string> skipped_failures;
  std::vector<std::string> not_started;  // another run (another sweep on this --out) is writing the log
  std::vector<std::string> replaced;     // a log of another scene lies under the point's name
  for (const SweepPoint& p : points) {
    if (shard && !shard->contains(p.index)) continue;
    ++counts.total;
    const PointStatus status = read_point_status(directory + "/" + kPointsFolder + "/" + p.log_name(), p.hash);
    if (status.state == PointState::completed) {
      ++counts.done;
    } else if (status.state == PointState::failed && !args.retry_failed) {
      ++counts.failed;
      skipped_failures.push_back(point_label(p, points.size()) + ": " + status.status);
    } else if (status.state == PointState::busy) {
      ++counts.interrupted;  // not completed by this invocation; the next one looks again
      not_started.push_back(point_label(p, points.size()) + ": " + status.status);
    } else {
      if (status.state == PointState::foreign) replaced.push_back(point_label(p, points.size()) + ": " + status.status);
      to_run.emplace_back(&p, status.continuable);
    }
  }
  const std::vector<RunSlot> slots = make_slots(args);
  SweepProgress progress(sweep.name, counts, std::min(slots.size(), std::max<std::size_t>(1, to_run.size())));
  progress.note(std::to_string(points.size()) + " points" +
                (shard ? " (shard " + shard->describe() + ": " + std::to_string(counts.total) + " of them)" : "") +
                ", logs in " + directory + "/" + kPointsFolder + ": " + std::to_string(counts.done) +
                " completed before, " + std::to_string(counts.failed) + " failed before, " +
                std::to_string(to_run.size()) + " to run, " + std::to_string(slots.size()) + " at a time");
  for (const std::string& f : skipped_failures) progress.note("not rerun (--retry-failed reruns it): " + f);
  for (const std::string& b : not_started) progress.note("not started, busy: " + b);
  for (const std::string& r : replaced) progress.note("run again, its log replaced: " + r);

  const std::string program = point_program();
  std::vector<PointTask> tasks;
  for (const auto& [p, continuable] : to_run) {
    tasks.push_back(make_task(*p, points.size(), sweep, args, program, directory, continuable));
  }
  fs::create_directories(directory + "/" + kPointsFolder);
  const RunnerReport report = run_point_tasks(tasks, slots, progress);

  if (!report.bad_input.empty()) {
    std::cerr << "error: " << report.bad_input;
    return kExitBadInput;
  }
  if (report.stopped_by_signal) {
    std::cerr << "sweep " << sweep.name << ": interrupted; " << report.interrupted
              << " point(s) in flight were stopped (with a checkpoint) and continue from it when the same command is "
                 "repeated\n";
    return kExitOther;
  }
  const SweepCounts& final_counts = progress.counts();
  std::cerr << "sweep " << sweep.name << ": " << final_counts.done << " of " << final_counts.total
            << " points completed, " << final_counts.failed << " failed, " << final_counts.interrupted
            << " did not complete\n";
  if (!shard) {
    // The summary of a sharded run is the merge's job: the shards end at different times.
    const int code = run_python_script(kSummaryScript, {directory});
    if (code != 0) {
      std::cerr << "error: the summary script exited with code " << code << "\n";
      return kExitOther;
    }
  }
  if (final_counts.interrupted > 0) return kExitOther;
  return final_counts.failed > 0 ? kExitSimulationFailure : kExitOk;
}

int run_script_on_directory(const char* script, const std::vector<std::string>& modules, const std::string& directory,
                            std::vector<std::string> extra) {
  if (!fs::is_regular_file(fs::path(directory) / kManifestName)) {
    throw InputError(directory + ": no " + std::string(kManifestName) + " here: not the --out folder of a sweep");
  }
  check_python_modules(modules);
  std::vector<std::string> arguments{directory};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return run_python_script(script, arguments);
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a parameter sweep (one `mssph run` per point), merge and plot it");
  cmd->add_option("sweep_file", args->sweep_file,
                  "Sweep file (JSON; keys in configs/README.md, schema configs/sweep.schema.json)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out,
                  "Output folder (default results/sweeps/<sweep name>): sweep.json, points/, summary.h5, summary.csv");
  cmd->add_option("--backend", args->backend, "Backend of every point, as for mssph run")
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--set", args->overrides,
                  "Override a scene value at every point, as for mssph run (e.g. simulation/particle_spacing=0.04 "
                  "for a coarse sweep)")
      ->allow_extra_args(false);
  cmd->add_option("--jobs", args->jobs, "Points run at once on the host (OMP_NUM_THREADS = cores / N each)")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  cmd->add_option("--gpus", args->gpus,
                  "Run one point per listed GPU at a time, e.g. --gpus 0,1 (each point's process sees only its GPU "
                  "through CUDA_VISIBLE_DEVICES)");
  cmd->add_option("--shard", args->shard,
                  "Run only shard K of N (points whose index i has i % N == K); inside a Slurm array job the shard "
                  "comes from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT (or _MIN/_MAX)");
  cmd->add_flag("--retry-failed", args->retry_failed,
                "Rerun points whose log says \"failed: ...\" (skipped by default)");
  cmd->add_option(
         "--checkpoint-interval", args->checkpoint_interval,
         "Each point's run writes a checkpoint every SECONDS of wall-clock time (as mssph run; a signal writes "
         "one anyway), so a point killed with its node loses at most that much")
      ->check(positive_finite_number());
  cmd->add_flag("--dry-run", args->dry_run, "Validate every point and list them with their logs' state; run nothing");
  cmd->add_flag(
      "--emit-slurm", args->emit_slurm,
      "Write Slurm scripts to DIR/slurm (an sbatch --array job and a dependent merge job) instead of running");
  cmd->add_option("--shards", args->shards, "With --emit-slurm: array tasks (default one per point, at most 1000)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--max-parallel", args->max_parallel, "With --emit-slurm: array tasks running at once (sbatch %N)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--partition", args->partition, "With --emit-slurm: sbatch --partition");
  cmd->add_option("--gpus-per-task", args->gpus_per_task, "With --emit-slurm: sbatch --gpus-per-task")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--cpus-per-task", args->cpus_per_task, "With --emit-slurm: sbatch --cpus-per-task")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--time", args->time_limit, "With --emit-slurm: sbatch --time of each array task, e.g. 02:00:00");
  cmd->add_option(
         "--sbatch-option", args->sbatch_options,
         "With --emit-slurm: an extra #SBATCH line for both jobs, e.g. --sbatch-option=--account=lab (repeatable)")
      ->allow_extra_args(false);
  cmd->footer(
      "Every point is checked by the scene loader before any runs; a point it rejects stops the sweep\n"
      "(exit code 2) naming the point, the JSON path and the reason. Each point's log is\n"
      "DIR/points/point-<hash>.h5, the hash naming the scene it runs (after every --set), with its\n"
      "parameters in the log's /tags attributes; its output goes to DIR/points/point-<hash>.out.\n"
      "\n"
      "Resume: the same command again skips points whose log says \"completed\"; points whose log says\n"
      "\"failed: ...\" are listed and rerun only with --retry-failed; anything else (no log, a log still\n"
      "\"running\" from a killed run, an interrupted one) runs again, from its log's latest checkpoint\n"
      "when it has one (mssph run --restart). SIGINT or SIGTERM stops the sweep: no new point starts\n"
      "and the running ones are stopped with a checkpoint (their logs say interrupted).\n"
      "\n"
      "Without --shard (and outside a Slurm array) a sweep ends by writing DIR/summary.h5 and\n"
      "DIR/summary.csv, as `mssph sweep merge DIR` does.\n"
      "\n"
      "Exit codes: 0 every point completed; 1 interrupted, or a point did not complete, or Python\n"
      "lacks h5py or NumPy (checked first: nothing runs), or another error; 2 bad input (sweep\n"
      "file, a point the scene loader rejects, arguments): nothing runs; 3 a point failed (its log is\n"
      "kept, marked \"failed: ...\").");

  auto merge_dir = std::make_shared<std::string>();
  CLI::App* merge = cmd->add_subcommand(
      "merge",
      "Summarise a sweep's folder: DIR/summary.h5 and DIR/summary.csv from the finished points; lists the missing");
  merge->add_option("dir", *merge_dir, "The sweep's --out folder")->required();
  merge->callback([merge_dir, &exit_code] {
    guarded(exit_code, [&] { return run_script_on_directory(kSummaryScript, kDataModules, *merge_dir, {}); });
  });

  auto plot_dir = std::make_shared<std::string>();
  auto plot_metric = std::make_shared<std::string>();
  CLI::App* plot = cmd->add_subcommand(
      "plot",
      "Plot a merged sweep: a metric against the first parameter, one line per value of the second, and a "
      "heat map for two parameters (PNG and SVG in DIR/plots)");
  plot->add_option("dir", *plot_dir, "The sweep's --out folder (merged)")->required();
  plot->add_option("--metric", *plot_metric, "The metric to plot (default: every numeric metric of the summary)");
  plot->callback([plot_dir, plot_metric, &exit_code] {
    guarded(exit_code, [&] {
      return run_script_on_directory(
          kPlotScript, kPlottingModules, *plot_dir,
          plot_metric->empty() ? std::vector<std::string>{} : std::vector<std::string>{"--metric", *plot_metric});
    });
  });

  cmd->callback([merge, plot, args, &exit_code] {
    if (merge->parsed() || plot->parsed()) return;
    guarded(exit_code, [&] {
      if (args->sweep_file.empty()) throw InputError("sweep: expected a sweep file, or merge DIR, or plot DIR");
      return run_sweep(*args);
    });
  });
}

}  // namespace mssph::cli
