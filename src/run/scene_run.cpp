#include "scene_run.hpp"

#include "backend_factory/backend_factory.hpp"
#include "backend_support.hpp"
#include "config/input_file.hpp"
#include "config/scene_loader.hpp"
#include "crowded_start.hpp"
#include "haptics/haptics_run.hpp"
#include "interrupt.hpp"
#include "io/output_claim.hpp"
#include "io/output_file.hpp"
#include "model/scene_builder.hpp"
#include "output_path.hpp"
#include "run_estimate.hpp"
#include "stability.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"
#include "util/threads.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace mssph::cli {
namespace {

// A closed stdout (`mssph run ... | head -0`) makes these writes fail with EPIPE (SIGPIPE is
// ignored): the run they describe has completed all the same, so their failure is not an error.
void print_summary_line(const std::string& output, const RunSummary& summary, const BackendInfo& info) {
  std::printf("%s: %zu steps, %.3f s simulated in %.2f s wall on %s (%s)", output.c_str(), summary.steps,
              summary.simulated_time, summary.wall_seconds, info.name.c_str(), info.device.c_str());
  if (!summary.force_body.empty()) {
    std::printf(", peak interaction force on %s %.3f N", summary.force_body.c_str(), summary.peak_force);
  }
  if (summary.peak_rendered_force) std::printf(", peak rendered force %.3f N", *summary.peak_rendered_force);
  if (!summary.outside_valid_range.empty()) {
    std::printf(", compressed beyond the material model's valid range in %s of logged samples",
                summary.outside_valid_range.c_str());
  }
  if (!summary.left_domain.empty()) std::printf(", left the domain: %s", summary.left_domain.c_str());
  std::printf("\n");
  std::fflush(stdout);
}

struct Tag {
  std::string name;
  nlohmann::json value;
};

// The longest tag name: an attribute's name lives in its object's header, whose messages HDF5
// caps at 64 KiB; 255 bytes is as long as any file name.
constexpr std::size_t kMaxTagNameBytes = 255;

// NAME=VALUE; NAME becomes an attribute name, so it is not empty and has no '/' (which h5py
// tools read as a path).
std::vector<Tag> parse_tags(const std::vector<std::string>& tags) {
  std::vector<Tag> out;
  for (const std::string& tag : tags) {
    const auto equals = tag.find('=');
    const std::string name = tag.substr(0, equals);
    if (equals == std::string::npos || name.empty() || name.find('/') != std::string::npos ||
        name.size() > kMaxTagNameBytes) {
      const std::string shown = tag.size() > 60 ? tag.substr(0, 60) + "..." : tag;
      throw InputError("--tag " + shown + ": expected NAME=VALUE with a NAME of at most " +
                       std::to_string(kMaxTagNameBytes) + " bytes, without '/'");
    }
    const std::string text = tag.substr(equals + 1);
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    if (value.is_discarded() || !value.is_number()) value = text;
    out.push_back({name, value});
  }
  return out;
}

void write_tags(RunLog& log, const std::vector<Tag>& tags) {
  for (const Tag& t : tags) {
    if (t.value.is_number_integer()) {
      log.set_attribute("/tags", t.name, t.value.get<long long>());
    } else if (t.value.is_number()) {
      log.set_attribute("/tags", t.name, t.value.get<double>());
    } else {
      log.set_attribute("/tags", t.name, t.value.get<std::string>());
    }
  }
}

// Where the log goes: --out, or the default path from the scene's name.
std::string output_of(const SceneRunRequest& request, const Scene& scene, const std::string& backend_name) {
  return request.output.empty() ? default_output_path(scene.name, backend_name) : request.output;
}

// No output may be one of the run's inputs or another of its outputs; none may replace anything
// but a regular file, and that only with --force. The outputs: the log and its partial file, the
// sidecars of a run that takes snapshots (<out>.xdmf, <out>.partial.xdmf), the stale <out>.xdmf
// that --force removes when the new log has none, and the recording.
void check_output_paths(const SceneRunRequest& request, const Scene& scene, const std::string& output) {
  std::vector<std::pair<std::string, std::string>> inputs{{request.scene_path, "the scene file"}};
  if (scene.proxy && !scene.proxy->haptics.trajectory.file.empty()) {
    inputs.emplace_back(scene.proxy->haptics.trajectory.file, "the scene's recorded trajectory");
  }
  const bool snapshots = scene.output.snapshot_interval > 0.0;
  std::vector<std::pair<std::string, std::string>> outputs{{output, "--out"}, {output + ".partial", "--out"}};
  if (snapshots) outputs.emplace_back(output + ".partial.xdmf", "--out");
  if (snapshots || request.force) outputs.emplace_back(output + ".xdmf", "--out");
  if (!request.record_device.empty()) outputs.emplace_back(request.record_device, "--record-device");
  for (const auto& [path, option] : outputs) {
    for (const auto& [input, what] : inputs) {
      if (same_file(path, input)) {
        throw InputError(option + " " + path + ": is " + what + " (" + input +
                         "), which the run reads; never "
                         "replaced, even with --force");
      }
    }
  }
  if (!request.record_device.empty()) {
    for (std::size_t i = 0; i + 1 < outputs.size(); ++i) {
      if (same_file(request.record_device, outputs[i].first)) {
        throw InputError("--record-device " + request.record_device +
                         ": the run writes its log (or the log's "
                         "partial file or sidecar) there");
      }
    }
  }
  check_output_path(output);
  check_claimable(output, request.force);
  if (snapshots) {
    check_output_file("--out", output + ".partial.xdmf", request.force);
    check_output_file("--out", output + ".xdmf", request.force);
  } else if (request.force) {
    check_replaceable("--out", output + ".xdmf", true);
  }
  if (!request.record_device.empty()) {
    check_device_recording_request(scene, request.record_device);
    check_output_file("--record-device", request.record_device, request.force);
  }
}

// As check_output_paths, saying where a default log path came from.
void check_outputs(const SceneRunRequest& request, const Scene& scene, const std::string& output) {
  try {
    check_output_paths(request, scene, output);
  } catch (const InputError& e) {
    if (!request.output.empty()) throw;
    throw InputError(std::string(e.what()) + " (the default --out, from /name of " + scene.source_file + ")");
  }
}

// A body's particles, and its lattice sites where it left out its interior (rigid_interior.hpp).
std::string particles_of(const BodySetup& body) {
  std::string text = std::to_string(body.count);
  if (body.count < body.lattice_sites) text += " of " + std::to_string(body.lattice_sites) + " lattice sites";
  return text;
}

void print_plan(const Scene& scene, const std::string& backend, const RunEstimate& estimate, const ParticleSetup& setup,
                const std::string& output, int threads) {
  std::ostringstream out;
  out << "dry run of " << scene.source_file << " (scene " << scene.name << ") on " << backend
      << ": nothing is written\n"
      << "  particles: " << setup.size() << "\n";
  for (const BodySetup& b : setup.bodies)
    out << "    " << b.name << " (" << to_string(b.kind) << "): " << particles_of(b) << "\n";
  out << "  memory estimate: host " << format_bytes(estimate.host_bytes);
  if (backend == "cuda") out << ", GPU " << format_bytes(estimate.device_bytes);
  if (const auto available = available_host_memory()) out << " (host available: " << format_bytes(*available) << ")";
  out << "\n  time step: dt = " << scene.simulation.dt << " s; upper bounds (docs/model.md):\n";
  for (const TimeStepBound& b : time_step_bounds(setup)) {
    out << "    " << b.body << " " << b.name << ": " << b.limit << " s (" << b.formula << ")"
        << (scene.simulation.dt > b.limit ? "  EXCEEDED" : "") << "\n";
  }
  out << "  steps: " << static_cast<long long>(std::llround(estimate.steps)) << " (duration "
      << scene.simulation.duration << " s)\n"
      << "  threads: " << threads << "\n"
      << "  log: " << output << "\n";
  std::cout << out.str() << std::flush;
}

// Why writing the log failed, as the user should read it (h5::Error already says "disk full
// writing <file>" when the file system said ENOSPC).
std::string write_failure(const std::exception& e) { return e.what(); }

// Runs a set-up run into its log and reports how it ended, as `mssph run` prints it.
SceneRunResult run_with_log(const Scene& scene, const ParticleSetup& setup, Backend& backend, RunLog& log,
                            const RunOptions& options, SceneRunResult result) {
  result.output = log.path();
  // A restart that ended before its first flush has not changed its log.
  const auto kept = [&log](const std::string& how) {
    return log.changed() ? "the log is kept, " + how + ": " + log.path() : log.path() + " is unchanged";
  };
  try {
    result.summary = run_simulation(scene, setup, backend, log, options);
    result.output = log.path();
    print_summary_line(result.output, result.summary, result.backend);
    result.exit_code = kExitOk;
    if (!result.summary.recording_error.empty()) {
      std::cerr << "error: " << result.summary.recording_error << "\n";
      result.exit_code = kExitOther;
      result.error = result.summary.recording_error;
    }
  } catch (const InputError&) {
    throw;  // a restart whose checkpoint does not fit the scene: the log stays as it was
  } catch (const SimulationFailure& e) {
    std::cerr << "error: " << e.what() << "\n  " << kept("marked failed") << "\n";
    result.exit_code = kExitSimulationFailure;
    result.error = e.what();
  } catch (const RunInterrupted& e) {
    std::cerr << "interrupted: " << e.what() << "\n  " << kept("marked interrupted") << "\n";
    result.exit_code = e.exit_code();
    result.error = std::string("interrupted: ") + e.what();
  } catch (const std::exception& e) {
    // A write failure (disk full), or a failure setting up the series or the haptic session: the
    // log ends with its reason, as far as the disk allows, at its partial name.
    if (!log.finished()) log.finish_failed(write_failure(e));
    std::cerr << "error: " << write_failure(e) << "\n  "
              << kept("with status \"failed: ...\" where the disk allowed writing it") << "\n";
    result.exit_code = kExitOther;
    result.error = write_failure(e);
  }
  result.output = log.path();
  return result;
}

// Options that would change a restarted run: it takes them from its log.
void check_restart_request(const SceneRunRequest& request) {
  const std::vector<std::pair<bool, const char*>> refused{{!request.scene_path.empty(), "a scene file"},
                                                          {!request.overrides.empty(), "--set"},
                                                          {request.backend != "auto", "--backend"},
                                                          {!request.output.empty(), "--out"},
                                                          {!request.record_device.empty(), "--record-device"},
                                                          {!request.tags.empty(), "--tag"},
                                                          {request.phase_timing, "--phase-timing"},
                                                          {request.force, "--force"},
                                                          {request.dry_run, "--dry-run"}};
  for (const auto& [given, what] : refused) {
    if (given) {
      throw InputError(std::string("--restart ") + request.restart + ": " + what +
                       " cannot be given with --restart; the run continues with the scene, backend and options "
                       "recorded in its log");
    }
  }
}

// A path the log recorded as the run was given it, taken from the folder where the run started
// (`working_directory`, "" in logs older than that attribute: then from here).
std::string from_run_folder(const std::string& path, const std::string& working_directory) {
  if (path.empty() || working_directory.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(working_directory) / path).string();
}

// What a restart writes besides its log, checked before the log is touched. A restart replaces
// no file (it takes no --force), so a file that appeared at one of these names since the run
// stopped is refused; the unfinished log's own sidecar is the restart's to rewrite.
void check_restart_outputs(const std::string& partial, const std::string& output, const Scene& scene,
                           const std::string& record_device) {
  const std::string option = "--restart " + partial + ":";
  std::vector<std::string> outputs;
  if (scene.output.snapshot_interval > 0.0) {
    check_replaceable(option, partial + ".xdmf", true);
    outputs.push_back(output + ".xdmf");
  }
  if (!record_device.empty()) outputs.push_back(record_device);
  for (const std::string& path : outputs) {
    std::error_code error;
    if (std::filesystem::exists(std::filesystem::symlink_status(path, error))) {
      throw InputError(option + " " + path +
                       ": exists, where the continued run writes; move it away (a restart "
                       "replaces no file)");
    }
    check_output_file(option, path, false);
  }
}

// `mssph run --restart LOG`: the run of LOG continued from its latest checkpoint, in the same
// log, with the same scene, backend and options.
SceneRunResult continue_run(const SceneRunRequest& request) {
  install_interrupt_handlers();
  check_restart_request(request);
  const std::string partial_suffix = ".partial";
  const bool names_partial = request.restart.size() > partial_suffix.size() &&
                             request.restart.compare(request.restart.size() - partial_suffix.size(),
                                                     partial_suffix.size(), partial_suffix) == 0;
  const std::string output =
      names_partial ? request.restart.substr(0, request.restart.size() - partial_suffix.size()) : request.restart;
  const std::string partial = output + partial_suffix;
  if (!std::filesystem::exists(partial) && std::filesystem::exists(output)) {
    throw InputError("--restart " + request.restart + ": the run completed (its log is " + output +
                     "); there is nothing to continue");
  }
  // Until the log is reopened for writing, a signal ends the process at once: the log is as it was.
  std::optional<EndAtOnceOnSignal> before_the_log;
  before_the_log.emplace("before the run continued; " + partial + " is unchanged");
  // The lock first: a run still writing the log is refused before anything reads it.
  OutputClaim claim = OutputClaim::resume(output);
  const RunLogHeader header = read_run_log_header(partial);
  const Scene scene = parse_scene_text(header.config, from_run_folder(header.config_path, header.working_directory));
  const std::string record_device = from_run_folder(header.record_device, header.working_directory);
  check_restart_outputs(partial, output, scene, record_device);
  const std::string backend_name = resolve_backend_name(header.backend);
  const RunEstimate estimate = estimate_run(scene, backend_name);
  check_run_fits(scene, backend_name, estimate, available_host_memory(), gpu_memory_for(backend_name));
  check_backend_supports(scene, backend_name);
  // A damaged step would make the run continue past its end (or before its start) for ever.
  if (header.checkpoint_step < -1 || header.checkpoint_step > std::llround(estimate.steps)) {
    throw InputError("--restart " + request.restart + ": its latest checkpoint says step " +
                     std::to_string(header.checkpoint_step) + ", outside the run's 0 to " +
                     std::to_string(std::llround(estimate.steps)) + " steps: the log is damaged");
  }
  const int threads = request.threads > 0 ? request.threads : default_thread_count();
  set_thread_count(threads);
  const ParticleSetup setup = build_particles(scene);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);

  SceneRunResult result;
  result.backend = backend->info();
  before_the_log.reset();
  if (const int signal = interrupt_signal()) {
    std::cerr << "error: " << signal_name(signal) << " before the run continued; " << partial << " is unchanged\n";
    result.exit_code = 128 + signal;
    result.error = "interrupted: " + signal_name(signal) + " before the run continued";
    return result;
  }
  RunLog log(std::move(claim), RunLog::Restart{command_line_of(request)});
  const double checkpoint_interval =
      request.checkpoint_interval > 0.0 ? request.checkpoint_interval : header.checkpoint_interval;
  log.set_attribute("/", "threads", static_cast<long long>(threads));
  log.set_attribute("/", "checkpoint_interval", checkpoint_interval);
  if (!request.quiet) {
    std::cerr << "mssph: " << scene.name << ": continuing " << partial << " from step " << log.restart_point()->step
              << " of " << std::llround(estimate.steps) << " on " << backend_name << ", " << threads << " threads\n";
  }
  return run_with_log(scene, setup, *backend, log,
                      RunOptions{request.quiet, record_device, header.phase_timing, checkpoint_interval, false},
                      std::move(result));
}

}  // namespace

std::string command_line_of(const SceneRunRequest& request) {
  if (!request.restart.empty()) {
    std::string line = "mssph run --restart " + request.restart;
    if (request.threads > 0) line += " --threads " + std::to_string(request.threads);
    if (request.checkpoint_interval > 0.0)
      line += " --checkpoint-interval " + std::to_string(request.checkpoint_interval);
    return line;
  }
  std::string line = "mssph run " + request.scene_path + " --backend " + request.backend;
  if (!request.output.empty()) line += " --out " + request.output;
  for (const std::string& o : request.overrides) line += " --set " + o;
  if (!request.record_device.empty()) line += " --record-device " + request.record_device;
  for (const std::string& t : request.tags) line += " --tag " + t;
  if (request.threads > 0) line += " --threads " + std::to_string(request.threads);
  if (request.phase_timing) line += " --phase-timing";
  if (request.checkpoint_interval > 0.0)
    line += " --checkpoint-interval " + std::to_string(request.checkpoint_interval);
  if (request.force) line += " --force";
  return line;
}

void check_scene_run(const SceneRunRequest& request) {
  const Scene scene = load_scene(request.scene_path, request.overrides);
  parse_tags(request.tags);
  check_outputs(request, scene, output_of(request, scene, resolve_backend_name(request.backend)));
}

SceneRunResult run_scene(const SceneRunRequest& request) {
  if (!request.restart.empty()) return continue_run(request);
  // Signals are caught from the start: one arriving while the scene loads or the particles and
  // the backend are set up ends the process at once (nothing is written then).
  install_interrupt_handlers();
  std::optional<EndAtOnceOnSignal> before_the_log;
  before_the_log.emplace("before the run started; nothing was written");
  // Everything that can be wrong with the input is found before the log file exists.
  // Read once: the text parsed is the text recorded, even from a pipe (/dev/stdin).
  const std::string scene_text = read_input_file(request.scene_path, "scene file");
  const Scene scene = parse_scene_text(scene_text, request.scene_path, request.overrides);
  const std::string backend_name = resolve_backend_name(request.backend);
  const std::vector<Tag> tags = parse_tags(request.tags);
  const std::string output = output_of(request, scene, backend_name);
  check_outputs(request, scene, output);
  // Checks of what the scene builds, after loading: a rejected value may still come from --set.
  const auto noting_overrides = [&](auto&& check) {
    try {
      return check();
    } catch (const InputError& e) {
      throw noting_override(e, request.overrides);
    }
  };
  const RunEstimate estimate = noting_overrides([&] { return estimate_run(scene, backend_name); });
  noting_overrides(
      [&] { check_run_fits(scene, backend_name, estimate, available_host_memory(), gpu_memory_for(backend_name)); });
  noting_overrides([&] { check_backend_supports(scene, backend_name); });
  const int threads = request.threads > 0 ? request.threads : default_thread_count();
  set_thread_count(threads);

  SceneRunResult result;
  ParticleSetup setup = noting_overrides([&] { return build_particles(scene); });
  if (request.dry_run) {
    print_plan(scene, backend_name, estimate, setup, output, threads);
    return result;
  }
  std::vector<std::string> warnings = stability_warnings(setup);
  for (std::string& w : haptic_warnings(scene, setup)) warnings.push_back(std::move(w));
  for (std::string& w : crowded_start_warnings(setup, scene.simulation.jitter)) warnings.push_back(std::move(w));
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";

  if (!request.quiet) {
    std::cerr << "mssph: " << scene.name << ": " << setup.size() << " particles (";
    for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
      std::cerr << (b ? ", " : "") << setup.bodies[b].name << " " << particles_of(setup.bodies[b]);
    }
    std::cerr << "), " << std::llround(estimate.steps) << " steps of " << scene.simulation.dt << " s on "
              << backend_name << ", " << threads << " threads ("
              << (request.threads > 0 ? std::string("--threads") : default_thread_source()) << "), OMP_WAIT_POLICY "
              << (std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "unset") << "\n";
  }
  const ParticleSetup setup_for_log = setup;
  std::unique_ptr<Backend> backend = make_backend(backend_name, std::move(setup));
  result.backend = backend->info();

  before_the_log.reset();
  if (const int signal = interrupt_signal()) {
    std::cerr << "error: " << signal_name(signal) << " before the run started; nothing was written\n";
    result.exit_code = 128 + signal;
    result.error = "interrupted: " + signal_name(signal) + " before the run started";
    return result;
  }

  RunMetadata metadata;
  metadata.version = build_info().version;
  metadata.git_commit = build_info().git_commit;
  metadata.backend = result.backend.name;
  metadata.device = result.backend.device;
  metadata.precision = result.backend.precision;
  metadata.scene_name = scene.name;
  metadata.config_path = scene.source_file;
  metadata.config_json = scene.document.dump(2);
  metadata.config_file = scene_text;
  metadata.seed = static_cast<long long>(scene.simulation.seed);
  metadata.command_line = command_line_of(request);

  std::unique_ptr<RunLog> log;
  try {
    // The claim (and its lock) is taken only now, so that a refused or interrupted set-up leaves
    // nothing behind; a run that took the path meanwhile makes this one fail here.
    log = std::make_unique<RunLog>(OutputClaim(output, request.force), metadata);
    std::string joined_warnings;
    for (const std::string& w : warnings) joined_warnings += w + "\n";
    log->set_attribute("/", "warnings", joined_warnings);
    log->set_attribute("/", "threads", static_cast<long long>(threads));
    // What a restart (--restart) takes from the log besides the scene and backend.
    log->set_attribute("/", "record_device", request.record_device);
    log->set_attribute("/", "working_directory", std::filesystem::current_path().string());
    log->set_attribute("/", "phase_timing", static_cast<long long>(request.phase_timing));
    log->set_attribute("/", "checkpoint_interval", request.checkpoint_interval);
    write_tags(*log, tags);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    // The log could not be started (disk full, I/O error): its partial file is removed.
    std::cerr << "error: " << write_failure(e) << "\n  nothing was written to " << output << "\n";
    result.exit_code = kExitOther;
    result.error = write_failure(e);
    return result;
  }

  return run_with_log(scene, setup_for_log, *backend, *log,
                      RunOptions{request.quiet, request.record_device, request.phase_timing,
                                 request.checkpoint_interval, request.force},
                      std::move(result));
}

}  // namespace mssph::cli
