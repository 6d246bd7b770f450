// Per-step time of the float32 backends: the paper's Figure 2 blocks (fluid, rigid, deformable)
// and the mixed scene with the coupled proxy, from 2k to 1M particles; one scene file's step;
// and the haptic tick. Each benchmark iteration runs a batch of steps and waits for the device
// once, so a GPU's asynchronous launches are timed as they run in a simulation.
#include "backend_factory/backend_factory.hpp"
#include "benchmark_suite.hpp"
#include "config/scene_loader.hpp"
#include "haptics/haptics_run.hpp"
#include "haptics/haptics_session.hpp"
#include "haptics/virtual_coupling.hpp"
#include "instruction_counts.hpp"
#include "machine_calibration.hpp"
#include "mixed_scene.hpp"
#include "model/block_scene.hpp"
#include "model/scene_builder.hpp"
#include "step_delay.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mssph::bench {
namespace {

constexpr int kBatch = 50;   // steps per timed iteration
constexpr int kWarmUp = 20;  // steps before timing: graph upload, caches, first grid
// Units of work in a counted region: enough steps to cover several neighbour-list rebuilds, and
// ticks to make the tick's count stand above the region's own overhead.
constexpr std::size_t kCountedSteps = 20;
constexpr std::size_t kCountedTicks = 2000;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A scene being stepped as `mssph run` steps it: the haptic session (when the scene has a proxy)
// sets the coupling wrench before each step. `state` (null when counting) receives the device
// memory counter.
class SteppedScene {
 public:
  SteppedScene(const Scene& scene, const std::string& backend_name, benchmark::State* state) {
    ParticleSetup setup = build_particles(scene);
    particles_ = static_cast<double>(setup.size());
    if (scene.proxy) haptics_.emplace(scene.proxy->haptics, proxy_model_of(scene, setup), scene.simulation.dt);
    if (const std::optional<std::size_t> bytes = backend_device_bytes(backend_name, setup); bytes && state) {
      state->counters["device_bytes_per_particle"] = static_cast<double>(*bytes) / particles_;
    }
    backend_ = make_backend(backend_name, std::move(setup));
  }

  // One step, and with the MSSPH_BENCH_EXTRA_STEP_EVERY test hook an extra one every N.
  void step() {
    advance();
    if (extra_every_ != 0 && ++requested_ % extra_every_ == 0) advance();
  }

  Backend& backend() { return *backend_; }
  double particles() const { return particles_; }
  bool coupled() const { return haptics_.has_value(); }
  double last_coupling_seconds() const { return last_coupling_seconds_; }

 private:
  void advance() {
    if (haptics_) {
      const auto start = Clock::now();
      haptics_->before_step(*backend_, steps_);
      last_coupling_seconds_ = seconds_since(start);
    }
    backend_->step();
    ++steps_;
  }

  std::unique_ptr<Backend> backend_;
  std::optional<HapticsSession> haptics_;
  std::size_t extra_every_ = extra_step_interval();
  std::size_t requested_ = 0;
  std::size_t steps_ = 0;
  double particles_ = 0.0;
  double last_coupling_seconds_ = 0.0;
};

void time_steps(benchmark::State& state, const Scene& scene, const std::string& backend_name) {
  const double delay = step_delay_seconds();
  SteppedScene sim(scene, backend_name, &state);
  for (int k = 0; k < kWarmUp; ++k) sim.step();
  sim.backend().synchronize();
  std::vector<std::string> phases = sim.backend().phase_names();
  if (sim.coupled()) phases.push_back("coupling");
  std::vector<double> phase_seconds(phases.size(), 0.0);
  const std::optional<std::uint64_t> builds_before = sim.backend().neighbour_grid_builds();
  for (auto _ : state) {
    const auto start = Clock::now();
    for (int k = 0; k < kBatch; ++k) {
      sim.step();
      busy_wait(delay);
    }
    sim.backend().synchronize();
    state.SetIterationTime(seconds_since(start));
    // The coupling phase is host wall time, including the wait for the proxy's read-back.
    if (sim.coupled()) phase_seconds.back() += sim.last_coupling_seconds();
  }
  // A backend that keeps neighbour lists rebuilds the grid on some steps only: how often it did
  // in the timed steps.
  if (builds_before) {
    const std::uint64_t builds = *sim.backend().neighbour_grid_builds() - *builds_before;
    state.counters["grid_builds_per_step"] =
        static_cast<double>(builds) / (static_cast<double>(state.iterations()) * kBatch);
  }
  // Where a step's time goes, from one further step per iteration with phase timing on (device
  // events on a GPU), outside the timed batches, whose steps the events would lengthen.
  sim.backend().set_phase_timing(true);
  for (benchmark::IterationCount k = 0; k < state.iterations(); ++k) {
    sim.step();
    const std::vector<double> last = sim.backend().last_phase_seconds();
    for (std::size_t p = 0; p < last.size(); ++p) phase_seconds[p] += last[p];
  }
  sim.backend().set_phase_timing(false);
  // A step that blew up times NaN arithmetic, not the simulation: such a run is an error.
  for (const BodyState& body : sim.backend().body_states()) {
    if (!std::isfinite(body.kinetic_energy)) {
      state.SkipWithError("the simulation blew up (non-finite kinetic energy): the time means nothing");
      return;
    }
  }
  for (std::size_t p = 0; p < phases.size(); ++p) {
    state.counters["phase_" + phases[p] + "_seconds"] = phase_seconds[p] / static_cast<double>(state.iterations());
  }
  state.counters["particles"] = sim.particles();
  // A backend that replays a captured step: its launch floor is set by how many nodes it holds.
  if (const auto graph = sim.backend().step_graph_size()) {
    state.counters["graph_nodes_per_step"] = static_cast<double>(graph->nodes);
    state.counters["graph_kernels_per_step"] = static_cast<double>(graph->kernels);
  }
  state.counters["step_seconds"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBatch,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One haptic tick as the haptic thread runs it: read the proxy's state back from the backend,
// evaluate the virtual coupling against a handle held 1 cm above it, hand the wrench back. With the
// MSSPH_BENCH_EXTRA_STEP_EVERY test hook, an extra tick every N.
class TickedProxy {
 public:
  TickedProxy(const std::string& backend_name, benchmark::State* state)
      : scene_(mixed_scene(2000)),
        sim_(scene_, backend_name, state),
        proxy_(proxy_model_of(scene_, build_particles(scene_))) {
    for (int k = 0; k < kWarmUp; ++k) sim_.step();
    sim_.backend().synchronize();
    handle_.position = sim_.backend().rigid_body_state(proxy_.body).centre_of_mass + Eigen::Vector3d(0.0, 0.0, 0.01);
  }

  void tick() {
    evaluate();
    if (extra_every_ != 0 && ++requested_ % extra_every_ == 0) evaluate();
  }

  double particles() const { return sim_.particles(); }

 private:
  void evaluate() {
    const BodyState s = sim_.backend().rigid_body_state(proxy_.body);
    const Pose pose{s.centre_of_mass, s.orientation};
    const Twist twist{s.linear_momentum / s.mass, s.angular_velocity};
    const Wrench w = spring_damper_wrench(scene_.proxy->haptics.coupling, handle_, Twist{}, pose, twist);
    sim_.backend().set_external_wrench(proxy_.body, w.force, w.torque);
  }

  Scene scene_;
  SteppedScene sim_;
  ProxyModel proxy_;
  Pose handle_;
  std::size_t extra_every_ = extra_step_interval();
  std::size_t requested_ = 0;
};

void time_haptic_tick(benchmark::State& state, const std::string& backend_name) {
  TickedProxy proxy(backend_name, &state);
  const double delay = step_delay_seconds();
  for (auto _ : state) {
    proxy.tick();
    busy_wait(delay);
  }
  state.counters["particles"] = proxy.particles();
}

// The counted twins of time_steps and time_haptic_tick: the same set-up and warm-up, then a fixed
// number of steps or ticks, so that a count is the same in every run of the same build.
void count_steps(const CountedRegion& region, const Scene& scene, const std::string& backend_name) {
  SteppedScene sim(scene, backend_name, nullptr);
  for (int k = 0; k < kWarmUp; ++k) sim.step();
  region.measure(kCountedSteps, [&] { sim.step(); });
}

void count_haptic_ticks(const CountedRegion& region, const std::string& backend_name) {
  TickedProxy proxy(backend_name, nullptr);
  region.measure(kCountedTicks, [&] { proxy.tick(); });
}

std::vector<long> sizes_for(const std::string& backend) {
  // The host runs the small sizes only: beyond 30k particles a step takes seconds there.
  if (backend == "cuda") return {2000, 5000, 10000, 30000, 100000, 300000, 1000000};
  return {2000, 5000, 10000, 30000};
}

}  // namespace

std::vector<std::string> default_benchmark_backends() {
  std::vector<std::string> backends;
  for (const std::string& backend : available_backends()) {
    if (backend == "reference") continue;
    if (!why_backend_cannot_run(backend).empty()) continue;  // e.g. built with CUDA, run without a GPU
    backends.push_back(backend);
  }
  return backends;
}

void register_suite(const std::vector<std::string>& backends) {
  using SceneOf = std::function<Scene(std::size_t)>;
  const std::vector<std::pair<std::string, SceneOf>> media{
      {"fluid", [](std::size_t n) { return block_scene(BodyKind::fluid, n); }},
      {"rigid", [](std::size_t n) { return block_scene(BodyKind::rigid, n); }},
      {"deformable", [](std::size_t n) { return block_scene(BodyKind::deformable, n); }},
      {"mixed", [](std::size_t n) { return mixed_scene(n); }}};
  register_calibration();
  for (const std::string& backend : backends) {
    for (const auto& [medium, scene_maker] : media) {
      const auto& scene_of = scene_maker;  // named again: Clang before 16 cannot capture a structured binding
      for (long n : sizes_for(backend)) {
        const std::string name = "step/" + backend + "/" + medium + "/" + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [backend, scene_of, n](benchmark::State& state) {
                                       time_steps(state, scene_of(static_cast<std::size_t>(n)), backend);
                                     })
            ->UseManualTime()
            ->Unit(benchmark::kMicrosecond);
        if (!backend_runs_on_gpu(backend)) {
          add_counted_workload(name, [backend, scene_of, n](const CountedRegion& region) {
            count_steps(region, scene_of(static_cast<std::size_t>(n)), backend);
          });
        }
      }
    }
    const std::string tick = "haptic_tick/" + backend;
    benchmark::RegisterBenchmark(tick.c_str(), time_haptic_tick, backend)->Unit(benchmark::kMicrosecond);
    if (!backend_runs_on_gpu(backend)) {
      add_counted_workload(tick, [backend](const CountedRegion& region) { count_haptic_ticks(region, backend); });
    }
  }
}

void register_scene_benchmark(const std::string& scene_path, const std::vector<std::string>& overrides,
                              const std::string& backend) {
  const Scene scene = load_scene(scene_path, overrides);
  build_particles(scene);  // a scene that cannot be built fails here, before any benchmark runs
  const std::string name = "scene/" + backend + "/" + scene.name;
  benchmark::RegisterBenchmark(name.c_str(),
                               [scene, backend](benchmark::State& state) { time_steps(state, scene, backend); })
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  if (!backend_runs_on_gpu(backend)) {
    add_counted_workload(name, [scene, backend](const CountedRegion& region) { count_steps(region, scene, backend); });
  }
}

}  // namespace mssph::bench
