// `mssph figure 2`: step time against particle count for each medium (Cirio et al. 2011,
// Figure 2), timed on one backend and written to DIR/figure2.h5; scripts/figures/figure2.py draws
// it and prints the fitted slopes next to the paper's.
#include "backend_factory/backend_factory.hpp"
#include "figure_command.hpp"
#include "io/run_log.hpp"
#include "model/block_scene.hpp"
#include "model/scene_builder.hpp"
#include "run/run_estimate.hpp"
#include "run/script_outputs.hpp"
#include "run/step_timing.hpp"
#include "util/build_info.hpp"
#include "util/errors.hpp"
#include "util/host_info.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace mssph::cli {
namespace {

BodyKind medium_of(const std::string& name) {
  if (name == "fluid") return BodyKind::fluid;
  if (name == "deformable") return BodyKind::deformable;
  if (name == "rigid") return BodyKind::rigid;
  throw InputError("--media: '" + name + "': expected fluid, deformable or rigid");
}

// The sizes to time: the given ones, then a 1-2-5 log scale above them up to --max (inclusive).
std::vector<long long> sizes_to_time(const Figure2Options& options, BlockGeometry geometry) {
  std::vector<long long> sizes = options.sizes;
  if (sizes.empty()) throw InputError("--sizes: expected at least one particle count");
  // The paper geometry needs one whole layer of its 0.5 m base at 2 cm spacing (25 x 25).
  const long long smallest = geometry == BlockGeometry::paper ? 625 : 100;
  for (long long n : sizes) {
    if (n < smallest) {
      throw InputError("--sizes: " + std::to_string(n) + ": expected particle counts >= " + std::to_string(smallest) +
                       " with --geometry " + to_string(geometry));
    }
  }
  std::sort(sizes.begin(), sizes.end());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  if (options.max_particles > 0 && options.max_particles < sizes.back()) {
    throw InputError("--max " + std::to_string(options.max_particles) + ": below the largest of --sizes (" +
                     std::to_string(sizes.back()) + ")");
  }
  for (long long decade = 10;; decade *= 10) {
    for (long long mantissa : {1, 2, 5}) {
      const long long n = mantissa * decade;
      if (n > sizes.back() && n <= options.max_particles) sizes.push_back(n);
    }
    if (decade > options.max_particles / 10) break;  // the next decade is beyond --max (and long long)
  }
  if (options.max_particles > sizes.back()) sizes.push_back(options.max_particles);
  return sizes;
}

// The largest size of every medium must fit this machine (particle indices, memory) before
// anything is built: a size of 3e9 is refused with its estimate, not met by std::bad_alloc.
void check_largest_size_fits(const Figure2Options& options, const std::vector<BodyKind>& media, BlockGeometry geometry,
                             const std::string& backend_name) {
  const long long largest_size = *std::max_element(options.sizes.begin(), options.sizes.end());
  const bool from_max = options.max_particles > largest_size;
  const long long largest = from_max ? options.max_particles : largest_size;
  const std::string option = (from_max ? "--max " : "--sizes ") + std::to_string(largest) + ": ";
  for (const BodyKind medium : media) {
    try {
      const Scene scene = block_scene(medium, static_cast<std::size_t>(largest), geometry);
      check_run_fits(scene, backend_name, estimate_run(scene, backend_name), available_host_memory(),
                     gpu_memory_for(backend_name));
    } catch (const InputError& e) {
      throw InputError(option + e.what());
    }
  }
}

RunMetadata figure_metadata(const BackendInfo& info, const nlohmann::json& parameters,
                            const std::string& command_line) {
  RunMetadata m;
  m.version = build_info().version;
  m.git_commit = build_info().git_commit;
  m.backend = info.name;
  m.device = info.device;
  m.precision = info.precision;
  m.scene_name = "figure2";
  m.config_json = parameters.dump(2);
  m.command_line = command_line;
  return m;
}

// The machine the timings belong to: what a reader needs to compare them with another's.
void record_machine(RunLog& log, const Figure2Options& options) {
  const BuildInfo& b = build_info();
  log.set_attribute("/", "host_cpu", host_cpu_name());
  log.set_attribute("/", "gpu_driver", gpu_driver_version());
  log.set_attribute("/", "build_type", b.build_type);
  log.set_attribute("/", "compiler", b.compiler);
  log.set_attribute("/", "geometry", options.geometry);
  log.set_attribute("/", "geometry_description",
                    options.geometry == "paper"
                        ? "0.5 m square base, fixed spacing 0.02 m (the paper's Figure 3 block), height from N"
                        : "0.5 x 0.5 x 0.2 m block, spacing from N");
  log.set_attribute("/", "timing",
                    "median over batches of steps, each batch closed by one device synchronisation, after a "
                    "warm-up; no logging or I/O inside the timed loop");
}

struct MediumSeries {
  std::size_t block_particles, particles, spacing, height, dt, step_time, steps, phase_time;
};

MediumSeries add_medium_series(RunLog& log, const std::string& medium, const std::vector<std::string>& phases) {
  const std::string g = "/figure2/" + medium;
  return MediumSeries{
      log.add_series(g + "/block_particles", 1, "1", "particles of the medium's block (the paper's abscissa)"),
      log.add_series(g + "/particles", 1, "1", "particles of the scene: block and container"),
      log.add_series(g + "/spacing", 1, "m", "particle spacing"),
      log.add_series(g + "/height", 1, "m", "block height"),
      log.add_series(g + "/dt", 1, "s", "simulated time step"),
      log.add_series(g + "/step_time", 3, "s", "wall-clock time of one step over the timed batches",
                     {"min", "median", "max"}),
      log.add_series(g + "/steps", 1, "1", "steps timed"),
      log.add_series(g + "/phase_time", phases.size(), "s", "mean time of each phase of a step", phases)};
}

void append(RunLog& log, std::size_t series, double value) { log.append(series, std::span<const double>(&value, 1)); }

// Times every medium at every size into the log's /figure2/<medium>/ series; a failure ends the
// log as failed, so a partial file is never taken for complete timings.
void time_all_sizes(RunLog& log, const Figure2Options& options, const std::vector<BodyKind>& media,
                    const std::vector<long long>& sizes, BlockGeometry geometry, const std::string& backend_name,
                    const StepTimingOptions& timing) {
  try {
    for (std::size_t m = 0; m < media.size(); ++m) {
      std::optional<MediumSeries> series;
      for (long long n : sizes) {
        const Scene scene = block_scene(media[m], static_cast<std::size_t>(n), geometry);
        ParticleSetup setup = build_particles(scene);
        const auto block_body = std::find_if(setup.bodies.begin(), setup.bodies.end(),
                                             [](const BodySetup& b) { return b.name == "block"; });
        const std::size_t block = block_body->count;
        const std::size_t total = setup.size();
        std::unique_ptr<Backend> backend = make_backend(backend_name, std::move(setup));
        const StepTimes t = time_steps(*backend, timing);
        if (!series) series = add_medium_series(log, options.media[m], t.phase_names);
        append(log, series->block_particles, static_cast<double>(block));
        append(log, series->particles, static_cast<double>(total));
        append(log, series->spacing, scene.simulation.particle_spacing);
        append(log, series->height, scene.find_body("block")->shape.size.z());
        append(log, series->dt, scene.simulation.dt);
        const std::vector<double> spread{t.min(), t.median(), t.max()};
        log.append(series->step_time, spread);
        append(log, series->steps, static_cast<double>(t.steps));
        log.append(series->phase_time, t.phase_seconds);
        const std::size_t samples =
            log.add_series("/figure2/" + options.media[m] + "/batches/" + std::to_string(n), 1, "s",
                           "per-step time of each timed batch of " + std::to_string(t.batch_steps) + " steps");
        for (double s : t.per_step_seconds) append(log, samples, s);
        log.flush();
        std::fprintf(
            stderr,
            "figure 2: %-10s %8zu particles (%zu with container): %.4g ms/step (min %.4g, max %.4g; %zu steps)\n",
            options.media[m].c_str(), block, total, 1e3 * t.median(), 1e3 * t.min(), 1e3 * t.max(), t.steps);
      }
    }
  } catch (const std::exception& e) {
    log.finish_failed(e.what());
    throw;
  }
  log.finish_completed();
}

}  // namespace

int make_figure2(const Figure2Options& options, const std::string& command_line) {
  std::vector<BodyKind> media;
  for (const std::string& m : options.media) media.push_back(medium_of(m));
  if (media.empty()) throw InputError("--media: expected at least one of fluid, deformable, rigid");
  const BlockGeometry geometry = block_geometry_from_string(options.geometry);
  const std::string backend_name = resolve_backend_name(options.backend);
  const std::vector<long long> sizes = sizes_to_time(options, geometry);
  check_largest_size_fits(options, media, geometry, backend_name);
  if (!(options.min_seconds > 0.0)) throw InputError("--min-time: expected a positive number of seconds");
  const std::string path = (std::filesystem::path(options.out) / "figure2.h5").string();
  check_script_outputs(options.out,
                       {"figure2.csv", "figure2.png", "figure2.svg", "figure2_loglog.png", "figure2_loglog.svg"},
                       options.force);

  // The backend's own description (device name) names the file's machine: build the smallest
  // scene once to ask it.
  const BackendInfo info =
      make_backend(backend_name, build_particles(block_scene(media.front(), sizes.front(), geometry)))->info();
  const nlohmann::json parameters = {{"media", options.media},
                                     {"sizes", sizes},
                                     {"geometry", options.geometry},
                                     {"backend", backend_name},
                                     {"min_time", options.min_seconds}};
  StepTimingOptions timing;
  timing.min_total_seconds = options.min_seconds;
  {
    RunLog log(path, figure_metadata(info, parameters, command_line), options.force);
    record_machine(log, options);
    time_all_sizes(log, options, media, sizes, geometry, backend_name, timing);
  }  // closed: the plotting script reads it
  std::cout << "figure 2: timings in " << path << std::endl;
  const auto arguments = [&](const std::string& folder) { return std::vector<std::string>{path, "--out", folder}; };
  return run_python_script_into("figures/figure2.py", arguments, options.out, options.force) == 0 ? kExitOk
                                                                                                  : kExitOther;
}

}  // namespace mssph::cli
