// Per-step time of the float32 backends on the paper's Figure 2 blocks (fluid, rigid,
// deformable) from 2k to 1M particles: the numbers behind results/ and the Figure 2
// reproduction. Each benchmark iteration runs a batch of steps and waits for the device once, so
// a GPU's asynchronous launches are timed as they run in a simulation.
#include "backend_factory.hpp"
#include "scene/block_scene.hpp"
#include "scene/scene_builder.hpp"
#ifdef MSSPH_HAVE_CUDA_BACKEND
#include "cuda/cuda_backend.hpp"
#endif

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

namespace {

constexpr int kBatch = 50;    // steps per timed iteration
constexpr int kWarmUp = 20;   // steps before timing: graph upload, caches, first grid

void step_time(benchmark::State& state, const std::string& backend_name, mssph::BodyKind medium) {
  const auto particles = static_cast<std::size_t>(state.range(0));
  mssph::ParticleSetup setup = mssph::build_particles(mssph::block_scene(medium, particles));
  const double total_particles = static_cast<double>(setup.size());
#ifdef MSSPH_HAVE_CUDA_BACKEND
  if (backend_name == "cuda") {
    state.counters["device_bytes_per_particle"] = static_cast<double>(mssph::kernels::cuda_backend_bytes(setup)) / total_particles;
  }
#endif
  std::unique_ptr<mssph::Backend> backend = mssph::make_backend(backend_name, std::move(setup));
  for (int k = 0; k < kWarmUp; ++k) backend->step();
  backend->synchronize();
  const std::vector<std::string> phases = backend->phase_names();
  std::vector<double> phase_seconds(phases.size(), 0.0);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < kBatch; ++k) backend->step();
    backend->synchronize();
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    // The phases of each batch's last step: where a step's time goes (device events on a GPU).
    const std::vector<double> last = backend->last_phase_seconds();
    for (std::size_t p = 0; p < phases.size(); ++p) phase_seconds[p] += last[p];
  }
  for (std::size_t p = 0; p < phases.size(); ++p) {
    state.counters["phase_" + phases[p] + "_seconds"] = phase_seconds[p] / static_cast<double>(state.iterations());
  }
  state.counters["particles"] = total_particles;
  state.counters["step_seconds"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kBatch, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void register_all() {
  const std::vector<std::pair<std::string, mssph::BodyKind>> media{
      {"fluid", mssph::BodyKind::fluid}, {"rigid", mssph::BodyKind::rigid}, {"deformable", mssph::BodyKind::deformable}};
  for (const std::string& backend : mssph::available_backends()) {
    if (backend == "reference") continue;
    if (backend == "cuda") {
#ifdef MSSPH_HAVE_CUDA_BACKEND
      if (mssph::kernels::cuda_devices().empty()) continue;  // built with CUDA, run without a GPU
#endif
    }
    // The host runs the small sizes only: beyond 30k particles a step takes seconds there.
    const std::vector<long> sizes = backend == "cuda" ? std::vector<long>{2000, 5000, 10000, 30000, 100000, 300000, 1000000}
                                                      : std::vector<long>{2000, 5000, 10000, 30000};
    for (const auto& [name, medium] : media) {
      auto* b = benchmark::RegisterBenchmark(("step/" + backend + "/" + name).c_str(), step_time, backend, medium);
      for (long n : sizes) b->Arg(n);
      b->UseManualTime()->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
