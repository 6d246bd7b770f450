// `mssph validate`: runs the validation cases of validation/ and writes the table, report.json,
// validation.h5 and report.md with plots.
#include "backend_factory/backend_factory.hpp"
#include "commands.hpp"
#include "framework/backends.hpp"
#include "framework/report.hpp"
#include "guarded.hpp"
#include "io/output_file.hpp"
#include "run/script_outputs.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"
#include "util/host_info.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <random>

namespace mssph::cli {
namespace {

using namespace mssph::validation;

struct ValidateArgs {
  bool quick = false;
  std::string backend = "auto";
  std::vector<std::string> suites;
  std::vector<std::string> cases;
  std::string out = "results/runs/validation";
  std::optional<std::uint64_t> seed;  // none: a fresh one
  bool force = false;                 // replace an earlier report's files in `out`
};

// "--seed 12": the digits of an unsigned 64-bit integer, nothing else (no sign, no fraction).
std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw InputError("--seed " + text + ": expected an integer from 0 to 18446744073709551615");
  }
  return seed;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

std::vector<std::string> gpu_names() {
  std::vector<std::string> names;
  for (const GpuDevice& d : gpu_devices()) names.push_back(d.name);
  return names;
}

// The cases the arguments select, in the registry's order. The self-test suite (cases whose
// expectation is wrong on purpose) runs only when named.
std::vector<const ValidationCase*> selected_cases(const ValidateArgs& args) {
  std::vector<const ValidationCase*> chosen;
  for (const std::string& name : args.cases) {
    const auto found =
        std::find_if(all_cases().begin(), all_cases().end(), [&](const ValidationCase& c) { return c.name == name; });
    if (found == all_cases().end()) {
      std::string known;
      for (const ValidationCase& c : all_cases()) known += (known.empty() ? "" : ", ") + c.name;
      throw InputError("--case " + name + ": no such case (known: " + known + ")");
    }
  }
  for (const ValidationCase& c : all_cases()) {
    const bool named = std::find(args.cases.begin(), args.cases.end(), c.name) != args.cases.end();
    const bool in_suite = std::find(args.suites.begin(), args.suites.end(), c.suite) != args.suites.end();
    if (!args.cases.empty()) {
      if (named && (args.suites.empty() || in_suite)) chosen.push_back(&c);
    } else if (args.suites.empty() ? c.suite != "selftest" : in_suite) {
      chosen.push_back(&c);
    }
  }
  if (chosen.empty()) throw InputError("--suite/--case: the selection names no case");
  return chosen;
}

// The files of the report, checked before any case runs: an earlier report's are replaced only with
// --force (regular files only), so a refused validation changes nothing in the folder. The plots
// are <suite>_<case>_<series>.png, and kernels_errors.png for the kernels suite; the cases' run
// logs go under runs/.
void check_report_outputs(const ValidateArgs& args, const std::vector<const ValidationCase*>& cases) {
  namespace fs = std::filesystem;
  const fs::path out(args.out);
  std::vector<std::string> names{"report.json", "validation.h5", "report.md"};
  if (std::any_of(cases.begin(), cases.end(), [](const ValidationCase* c) { return c->suite == "kernels"; })) {
    names.push_back("kernels_errors.png");
  }
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(out, error)) {
    const std::string name = entry.path().filename().string();
    for (const ValidationCase* c : cases) {
      const std::string prefix = c->suite + "_" + c->name + "_";
      if (name.rfind(prefix, 0) == 0 && entry.path().extension() == ".png") names.push_back(name);
    }
  }
  check_script_outputs(args.out, names, args.force);
  const fs::path runs = out / "runs";
  if (!args.force && fs::is_directory(runs, error) && !fs::is_empty(runs, error)) {
    throw InputError("--out " + args.out + ": " + runs.string() +
                     " holds the run logs of an earlier validation; pass --force to replace them, or choose another "
                     "folder");
  }
}

// The command that repeats the run into a fresh --out: with the seed it used, fresh or given.
std::string command_line(const ValidateArgs& args, std::uint64_t seed) {
  std::string line = "mssph validate";
  if (args.quick) line += " --quick";
  line += " --backend " + args.backend;
  for (const std::string& s : args.suites) line += " --suite " + s;
  for (const std::string& c : args.cases) line += " --case " + c;
  line += " --seed " + std::to_string(seed);
  line += " --out " + args.out;
  return line;
}

int run_validate(const ValidateArgs& args) {
  const std::vector<const ValidationCase*> cases = selected_cases(args);
  std::error_code error;
  if (std::filesystem::exists(args.out, error) && !std::filesystem::is_directory(args.out, error)) {
    throw InputError("--out " + args.out + ": not a directory (the report, its plots and runs go into a folder)");
  }
  check_report_outputs(args, cases);

  CaseContext context;
  context.quick = args.quick;
  context.seed = args.seed ? *args.seed : std::random_device{}();
  context.validation_dir = validation_dir();
  context.work_dir = (std::filesystem::path(args.out) / "runs").string();
  context.replace_logs = args.force;
  if (args.backend == "auto") {
    context.physics_backend = resolve_backend_name("auto");
  } else {
    context.physics_backend = args.backend;
    context.physics_backend_skip = why_backend_cannot_run(args.backend);
  }
  // The kernels suite compares the chosen float32 backend with the reference, or every one.
  const std::vector<std::string> float_backends = float_backend_names();
  if (std::find(float_backends.begin(), float_backends.end(), args.backend) != float_backends.end()) {
    context.fast_backends = {args.backend};
  } else {
    context.fast_backends = float_backends;
  }

  RunInfo info;
  info.mssph_version = build_info().version;
  info.git_commit = build_info().git_commit;
  info.date = utc_now();
  info.command_line = command_line(args, context.seed);
  info.mode = args.quick ? "quick" : "full";
  info.physics_backend = context.physics_backend;
  info.physics_precision = context.physics_backend == "reference" ? "float64" : "float32";
  info.host_cpu = host_cpu_name();
  info.gpus = gpu_names();
  info.physics_device =
      context.physics_backend == "cuda" ? (info.gpus.empty() ? "no GPU" : info.gpus.front()) : info.host_cpu;
  info.fast_backends = context.fast_backends;
  info.seed = context.seed;

  if (std::filesystem::create_directories(context.work_dir, error); error) {
    throw InputError("--out " + args.out + ": cannot create " + context.work_dir + " (" + error.message() + ")");
  }
  std::cerr << "mssph validate: " << cases.size() << " case(s), " << info.mode << ", physics on "
            << context.physics_backend << ", seed " << context.seed << "\n";
  std::vector<CaseRun> runs;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const ValidationCase& c = *cases[k];
    std::cerr << "validate: [" << k + 1 << "/" << cases.size() << "] " << c.suite << "/" << c.name << ": " << c.title
              << "\n";
    CaseRun run;
    run.which = &c;
    const auto start = std::chrono::steady_clock::now();
    try {
      run.result = c.run(context);
    } catch (const std::exception& e) {
      run.error = e.what();
    }
    run.result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << "validate: " << c.name << ": " << status_name(case_status(run)) << " in " << run.result.wall_seconds
              << " s" << (run.error.empty() ? "" : " (" + run.error + ")") << "\n";
    runs.push_back(std::move(run));
  }

  print_table(info, runs);
  const std::string json_path = (std::filesystem::path(args.out) / "report.json").string();
  const std::string h5_path = (std::filesystem::path(args.out) / "validation.h5").string();
  OutputFile(json_path, args.force).write(report_json_text(info, runs));
  OutputFile(h5_path, args.force).write(report_hdf5_image(info, runs));
  const int plotted = run_python_script_into(
      "validation/report.py",
      [&](const std::string& folder) {
        return std::vector<std::string>{json_path, h5_path, folder};
      },
      args.out, args.force);
  if (plotted != 0) {
    std::cerr << "error: scripts/validation/report.py failed (exit " << plotted << "): " << args.out
              << "/report.md is missing or incomplete\n";
    return kExitOther;
  }
  std::printf("report: %s/report.md, %s, %s\n", args.out.c_str(), json_path.c_str(), h5_path.c_str());
  const bool failed =
      std::any_of(runs.begin(), runs.end(), [](const CaseRun& r) { return case_status(r) == Status::fail; });
  return failed ? kExitOther : kExitOk;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand("validate", "Run the validation cases (validation/) and write a report");
  cmd->add_flag("--quick", args->quick, "Coarse resolutions: the whole run in minutes on 2 CPU cores (what CI runs)");
  cmd->add_option("--backend", args->backend,
                  "Backend of the physics cases (reference, cpu, cuda, auto); the kernels suite compares it (or, for "
                  "auto and reference, every float32 backend) with the reference")
      ->check(CLI::IsMember(backend_choices()))
      ->capture_default_str();
  cmd->add_option("--suite", args->suites, "Run only this suite: kernels, physics, convergence (repeatable)")
      ->check(CLI::IsMember({"kernels", "physics", "convergence", "selftest"}));
  cmd->add_option("--case", args->cases,
                  "Run only the named case (repeatable); names are in the table and validation/");
  cmd->add_option("--out", args->out, "Output folder for report.md, report.json, validation.h5 and plots")
      ->capture_default_str();
  // Read as text: CLI11 would wrap "-1" to 2^64 - 1 in an unsigned integer.
  auto seed_text = std::make_shared<std::string>();
  cmd->add_option("--seed", *seed_text, "Seed of the random perturbations, 0 to 2^64 - 1 (default: fresh, printed)");
  cmd->add_flag("--force", args->force,
                "Replace an earlier report's files and run logs in --out (regular files only, never a directory, "
                "device or symbolic link)");
  cmd->footer(
      "Each case states its expectation (formula and source), tolerance and reason in\n"
      "validation/<suite>/<case>/README.md. A case that cannot run here (e.g. cuda without a GPU) is\n"
      "SKIPPED with the reason, never PASS.\n"
      "\n"
      "An earlier report in --out is replaced only with --force.\n"
      "\n"
      "Exit codes: 0 every case passed or was skipped; 1 a case failed, the report could not be\n"
      "written, or Python lacks h5py, NumPy or matplotlib (checked first: nothing is run); 2 bad\n"
      "arguments, or an earlier report in the way (nothing is run).");
  cmd->callback([args, seed_text, &exit_code] {
    guarded(exit_code, [&] {
      if (!seed_text->empty()) args->seed = parse_seed(*seed_text);
      return run_validate(*args);
    });
  });
}

}  // namespace mssph::cli
