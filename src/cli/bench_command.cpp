// `mssph bench`: the benchmark suite (benchmarks/benchmark_suite.hpp) run in-process through
// Google Benchmark, writing its JSON with the machine context; and `mssph bench compare`: the
// significance-gated comparison of two such files (src/bench/).
#include "backend_factory/backend_factory.hpp"
#include "bench/bench_comparison.hpp"
#include "bench/benchmark_results.hpp"
#include "bench/comparison_format.hpp"
#include "benchmark_suite.hpp"
#include "commands.hpp"
#include "guarded.hpp"
#include "instruction_counts.hpp"
#include "io/output_claim.hpp"
#include "run/output_path.hpp"
#include "step_delay.hpp"
#include "util/errors.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace mssph::cli {
namespace {

struct BenchArgs {
  std::vector<std::string> backends;
  std::string filter;
  int repetitions = 5;
  double min_time = 0.0;  // 0: Google Benchmark's default (0.5 s)
  std::string out;
  bool list = false;
  bool force = false;
  bool count_instructions = false;
  std::string counting_filter;  // set in the counting run under Callgrind: the benchmarks to count
  std::string scene;
  std::vector<std::string> overrides;
};

struct CompareArgs {
  std::string baseline;
  std::string current;
  std::string gate = "time";
  std::string threshold;  // empty: 10% on wall time, 3% on instructions
  double alpha = 0.05;
  std::string format = "table";
  bool force = false;
  std::string normalize_by;  // empty: none
};

// "10%" or "0.1" -> 0.1.
double parse_threshold(const std::string& text) {
  std::string number = text;
  const bool percent = !number.empty() && number.back() == '%';
  if (percent) number.pop_back();
  std::size_t used = 0;
  double value = -1.0;
  try {
    value = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const double fraction = percent ? value / 100.0 : value;
  // Above 10 (1000%) a gate could hardly fail, and inf or nan never would.
  if (used == 0 || used != number.size() || !(fraction > 0.0) || !(fraction <= 10.0)) {
    throw InputError("--threshold " + text +
                     ": expected a positive fraction or percentage up to 10 (1000%), e.g. 10% or 0.1");
  }
  return fraction;
}

// The Google Benchmark command line that the options stand for.
std::vector<std::string> benchmark_flags(const BenchArgs& a) {
  std::vector<std::string> flags{"mssph bench"};
  if (!a.filter.empty()) flags.push_back("--benchmark_filter=" + a.filter);
  flags.push_back("--benchmark_repetitions=" + std::to_string(a.repetitions));
  // Repetitions of different benchmarks run in random order, so a slow phase of a shared
  // machine spreads over all of them instead of biasing one benchmark.
  flags.push_back("--benchmark_enable_random_interleaving=true");
  if (a.min_time > 0.0) flags.push_back("--benchmark_min_time=" + std::to_string(a.min_time));
  if (!a.out.empty()) {
    flags.push_back("--benchmark_out=" + a.out);
    flags.push_back("--benchmark_out_format=json");
  }
  if (a.list) flags.push_back("--benchmark_list_tests=true");
  return flags;
}

void register_benchmarks(const BenchArgs& a) {
  if (a.scene.empty() && !a.overrides.empty())
    throw InputError("--set applies to a scene file: mssph bench SCENE.json --set ...");
  if (!a.scene.empty()) {
    for (const std::string& backend : a.backends.empty() ? std::vector<std::string>{"auto"} : a.backends) {
      bench::register_scene_benchmark(a.scene, a.overrides, resolve_backend_name(backend));
    }
  } else {
    std::vector<std::string> backends;
    for (const std::string& b : a.backends) backends.push_back(resolve_backend_name(b));
    bench::register_suite(backends.empty() ? bench::default_benchmark_backends() : backends);
  }
}

// The name as the suite registers it: Google Benchmark appends /manual_time to manually timed ones.
std::string registered_name(std::string name) {
  const std::string suffix = "/manual_time";
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
    name.resize(name.size() - suffix.size());
  }
  return name;
}

// This program's arguments for the counting run of the benchmarks in the results file.
std::vector<std::string> counting_arguments(const BenchArgs& a, const std::string& results_path) {
  std::string alternatives;
  for (const std::string& name : bench::read_benchmark_results(results_path).names) {
    const std::string escaped =
        std::regex_replace(registered_name(name), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
    alternatives += (alternatives.empty() ? "" : "|") + escaped;
  }
  std::vector<std::string> args{std::filesystem::read_symlink("/proc/self/exe").string(), "bench"};
  if (!a.scene.empty()) args.push_back(a.scene);
  for (const std::string& b : a.backends) args.insert(args.end(), {"--backend", b});
  for (const std::string& o : a.overrides) args.insert(args.end(), {"--set", o});
  args.insert(args.end(), {"--counting-filter", "^(" + alternatives + ")$"});
  return args;
}

// Counts the instructions of the benchmarks in `results_path` under Callgrind and adds them there.
void add_instruction_counts(const BenchArgs& a, const std::string& results_path) {
  const std::filesystem::path dir = std::filesystem::path(results_path + ".callgrind");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directory(dir);
  std::cerr << "mssph bench: counting instructions under Callgrind" << std::endl;
  const std::vector<bench::InstructionCount> counts =
      bench::count_instructions(counting_arguments(a, results_path), dir.string());
  std::filesystem::remove_all(dir);
  bench::add_counts_to_benchmark_file(results_path, counts);
}

int run_bench(const BenchArgs& a) {
  bench::step_delay_seconds();  // a malformed test hook is bad input before anything runs
  bench::extra_step_interval();
  register_benchmarks(a);
  if (!a.counting_filter.empty()) {
    if (bench::run_counted_workloads(a.counting_filter) == 0) {
      throw InputError("no counted workload matches " + a.counting_filter);
    }
    return kExitOk;
  }
  if (a.count_instructions && a.out.empty()) throw InputError("--count-instructions: give --out FILE.json");
  // The results go to <out>.partial, held by this run, and reach <out> only once whole.
  std::optional<OutputClaim> claim;
  if (!a.out.empty()) {
    check_output_path(a.out);
    claim.emplace(a.out, a.force);
  }
  BenchArgs google_benchmark_args = a;
  if (claim) google_benchmark_args.out = claim->partial_path();
  bench::add_machine_context();
  std::vector<std::string> flags = benchmark_flags(google_benchmark_args);
  std::vector<char*> argv;
  for (std::string& f : flags) argv.push_back(f.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (ran == 0 && !a.list) {
    throw InputError("no benchmark matches --filter \"" + a.filter + "\" (mssph bench --list names them)");
  }
  if (!claim) return kExitOk;
  try {
    bench::null_for_values_without_json_literal(claim->partial_path());
    bench::read_benchmark_results(claim->partial_path());  // what was written is whole and readable
  } catch (const InputError& e) {
    throw std::runtime_error(std::string("writing the results failed: ") + e.what());
  }
  if (a.count_instructions) add_instruction_counts(a, claim->partial_path());
  claim->publish();
  std::cerr << "mssph bench: wrote " << a.out << "\n";
  return kExitOk;
}

int run_compare(const CompareArgs& a) {
  bench::CompareOptions options;
  options.gate = a.gate == "instructions" ? bench::GateMeasure::instructions : bench::GateMeasure::wall_time;
  const bool counts = options.gate == bench::GateMeasure::instructions;
  options.threshold = parse_threshold(!a.threshold.empty() ? a.threshold : counts ? "3%" : "10%");
  options.alpha = a.alpha;
  options.force = a.force;
  if (!a.normalize_by.empty()) options.normalize_by = a.normalize_by;
  const bench::BenchmarkResults baseline = bench::read_benchmark_results(a.baseline);
  const bench::BenchmarkResults current = bench::read_benchmark_results(a.current);
  const bench::ComparisonReport report = bench::compare(baseline, current, options);
  const bench::ReportFormat format = a.format == "json"       ? bench::ReportFormat::json
                                     : a.format == "markdown" ? bench::ReportFormat::markdown
                                                              : bench::ReportFormat::table;
  std::cout << bench::format_report(report, format);
  return report.failed() ? kExitOther : kExitOk;
}

void add_compare_command(CLI::App& bench, int& exit_code) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = bench.add_subcommand("compare", "Compare two benchmark files: median ratios, significance, verdicts");
  cmd->add_option("baseline", args->baseline, "Baseline results (Google Benchmark JSON)")->required();
  cmd->add_option("current", args->current, "Current results (Google Benchmark JSON)")->required();
  cmd->add_option("--gate", args->gate,
                  "The measure the gate judges: time (medians and a significance test; a quiet machine, GPUs) or "
                  "instructions (per step, from `mssph bench --count-instructions`; a shared runner)")
      ->check(CLI::IsMember({"time", "instructions"}))
      ->capture_default_str();
  cmd->add_option("--threshold", args->threshold,
                  "Slowdown that fails the gate: a ratio above 1 + threshold, significant on time (default 10%), any "
                  "on instructions (default 3%); as 10% or 0.1");
  cmd->add_option("--alpha", args->alpha, "Significance level of the Mann-Whitney U test")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  cmd->add_option("--format", args->format, "table (terminal), markdown (CI job summary) or json")
      ->check(CLI::IsMember({"table", "markdown", "json"}))
      ->capture_default_str();
  cmd->add_flag("--force", args->force, "Compare files from different machines or build types anyway");
  cmd->add_option("--normalize-by", args->normalize_by,
                  "A benchmark in both files that times the machine (calibration/cpu): divide out how much slower "
                  "the current file's machine ran it");
  cmd->footer(
      "For each benchmark in both files: the median over its repetitions in each (Google Benchmark's\n"
      "per-repetition entries; mean/median/stddev aggregates are ignored), the ratio current/baseline,\n"
      "and a two-sided Mann-Whitney U test of the two sets of repetitions: exact when neither side\n"
      "has more than 20 repetitions and no times tie, else the normal approximation with tie and\n"
      "continuity correction; significant when p < alpha (0.05). Verdicts: SLOWER (ratio above\n"
      "1 + threshold and significant), faster (below 1 / (1 + threshold) and significant), unchanged\n"
      "(within the threshold), not significant (beyond it, but noise cannot be ruled out), too few\n"
      "repetitions (with 3 or fewer per side no p-value falls below 0.05: run at least 4).\n"
      "\n"
      "The files must come from the same machine and build: their context's mssph_cpu, mssph_gpu and\n"
      "mssph_build_type must agree, else the comparison is refused (naming the field) unless --force.\n"
      "A shared machine's speed still drifts between hours; --normalize-by calibration/cpu divides\n"
      "each ratio by the ratio of that fixed workload's medians.\n"
      "\n"
      "--gate instructions judges instructions per step instead (files from `mssph bench\n"
      "--count-instructions`): counted by Callgrind, they are the same for the same build whatever\n"
      "else the machine runs, so any ratio above 1 + threshold (default 3%) fails, with no test; wall\n"
      "time is shown beside them. Only mssph_build_type and mssph_compiler must agree. This is the\n"
      "gate for a shared CI runner (scripts/bench_gate.sh); wall time stays the gate of a quiet,\n"
      "dedicated machine and of GPUs.\n"
      "\n"
      "Exit codes: 0 no benchmark slower beyond the threshold; 1 at least one; 2 bad input (a missing\n"
      "or unreadable file, not Google Benchmark JSON, a time or count that is not positive, no\n"
      "benchmark in common, no counts for the instruction gate, different machines without --force).");
  cmd->callback([args, &exit_code] { guarded(exit_code, [&] { return run_compare(*args); }); });
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd =
      app.add_subcommand("bench", "Time the simulation step per backend, medium and size (Google Benchmark)");
  cmd->require_subcommand(0, 1);
  cmd->add_option("scene", args->scene,
                  "Time one step of this scene file instead of the suite (scene/<backend>/<name>)")
      ->check(CLI::ExistingFile);
  std::string built;
  for (const std::string& name : available_backends()) built += (built.empty() ? "" : ", ") + name;
  cmd->add_option("--backend", args->backends,
                  "Backend to time (repeatable): cpu, cuda, reference or auto. Default: the suite on cpu and, "
                  "with a GPU, cuda; a scene on auto. This build has: " +
                      built)
      ->check(CLI::IsMember(backend_choices()));
  cmd->add_option("--filter", args->filter,
                  "Only benchmarks whose name matches this regular expression, "
                  "e.g. 'step/cpu/fluid/2000' or 'step/cuda'");
  cmd->add_option("--repetitions", args->repetitions,
                  "Repetitions of each benchmark (compare needs at least 4 per side to find anything significant)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--min-time", args->min_time, "Minimum seconds of each repetition (default Google Benchmark's 0.5)")
      ->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--out", args->out,
                  "Write the results as Google Benchmark JSON with the machine context to FILE.json");
  cmd->add_option("--set", args->overrides, "With a scene: override a scene value, PATH=VALUE (as mssph run)")
      ->allow_extra_args(false);
  cmd->add_flag("--list", args->list, "List the benchmark names (after --filter) without running them");
  cmd->add_flag("--force", args->force, "Replace an existing --out file");
  cmd->add_flag("--count-instructions", args->count_instructions,
                "Also count each host benchmark's instructions per step under Valgrind's Callgrind "
                "(single-threaded, unaffected by other load) and add them to --out as instructions_per_step and "
                "ll_misses_per_step");
  cmd->add_option("--counting-filter", args->counting_filter)->group("");  // the counting run under Callgrind
  cmd->footer(
      "Benchmarks (stable names, so that files compare across commits):\n"
      "  step/<backend>/<medium>/<particles>/manual_time  one step of a block of fluid, rigid or\n"
      "      deformable medium (the paper's Figure 2 block), or of the mixed scene (fluid pool,\n"
      "      deformable block and the coupled haptic proxy), with about <particles> particles; the\n"
      "      host runs 2k-30k, cuda 2k-1M. Timed per batch of 50 steps after the device finished;\n"
      "      counters: step_seconds, particles and phase_<name>_seconds for the phases of a step.\n"
      "  haptic_tick/<backend>  one coupling evaluation plus the proxy's read-back.\n"
      "  scene/<backend>/<name>/manual_time  with SCENE.json: one step of that scene.\n"
      "  calibration/cpu  a fixed workload (gathered float sums, no mssph code) that times the\n"
      "      machine itself, for 'mssph bench compare --normalize-by calibration/cpu'.\n"
      "The output's context records the machine and build: mssph_cpu, mssph_cpu_cores, mssph_gpu,\n"
      "mssph_gpu_driver, mssph_cuda_backend, mssph_build_type, mssph_git_commit, mssph_compiler.\n"
      "Repetitions run interleaved in random order. The console table goes to stdout.\n"
      "\n"
      "Test hook: MSSPH_BENCH_STEP_DELAY_US=N busy-waits N microseconds after every benchmarked step\n"
      "(and haptic tick), a known slowdown for testing the gate; it is recorded in the context as\n"
      "mssph_test_step_delay_us. Never set it for real measurements. On cuda the wait overlaps the\n"
      "GPU's work. MSSPH_BENCH_EXTRA_STEP_EVERY=N takes one extra step after every N benchmarked\n"
      "steps (and ticks): 1/N more of the same work, which instruction counts see (recorded as\n"
      "mssph_test_extra_step_every).\n"
      "\n"
      "--count-instructions: after the timed runs, this program runs again under\n"
      "`valgrind --tool=callgrind` (Debian's valgrind), which counts each host benchmark's\n"
      "instructions over 20 steps (or 2000 ticks) after the same warm-up, with fixed simulated caches;\n"
      "--out then carries instructions_per_step and ll_misses_per_step for `bench compare --gate\n"
      "instructions`. GPU benchmarks are not counted.\n"
      "\n"
      "mssph bench compare BASELINE.json CURRENT.json: see 'mssph bench compare --help'.\n"
      "\n"
      "Exit codes: 0 ok; 1 other error; 2 bad input (scene, --set, --backend, --out, --filter that\n"
      "matches nothing, a malformed MSSPH_BENCH_STEP_DELAY_US).");
  add_compare_command(*cmd, exit_code);
  CLI::App* compare = cmd->get_subcommand("compare");
  cmd->callback([args, compare, &exit_code] {
    if (compare->parsed()) return;  // `mssph bench compare ...` ran its own callback
    guarded(exit_code, [&] { return run_bench(*args); });
  });
}

}  // namespace mssph::cli
