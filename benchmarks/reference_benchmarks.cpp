// Google Benchmark timings of the double-precision reference: neighbour search and whole steps
// for blocks of each medium. The reference is the oracle, not the fast path; these numbers say
// how large a scene the validation suite can afford.
#include "config/scene_loader.hpp"
#include "neighbour_search.hpp"
#include "reference_backend.hpp"
#include "scene/scene_builder.hpp"

#include <benchmark/benchmark.h>

namespace {

// A block of `medium` with about `particles` particles on a ground plate (the paper's Figure 2
// scene: a cuboid of square base 0.5 m whose height follows the particle count).
mssph::Scene block_scene(const std::string& medium, long particles) {
  const double dx = 0.02;
  const double base = 0.5;
  const double height = std::max(dx, static_cast<double>(particles) * dx * dx * dx / (base * base));
  nlohmann::json scene = {
      {"name", "bench_" + medium},
      {"simulation", {{"dt", 1e-4}, {"duration", 1.0}, {"particle_spacing", dx}}},
      {"materials", {{"m", {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}, {"viscosity", 1.0}}}}},
      {"bodies",
       {{"ground", {{"kind", "boundary"}, {"shape", {{"type", "box"}, {"size", {base + 0.1, base + 0.1, 2 * dx}}}},
                    {"position", {0.0, 0.0, -dx}}, {"material", "m"}}},
        {"block", {{"kind", medium}, {"shape", {{"type", "box"}, {"size", {base, base, height}}}},
                   {"position", {0.0, 0.0, 0.5 * height + 0.5 * dx}}, {"material", "m"}}}}}};
  if (medium == "rigid") scene["bodies"]["block"]["density"] = 1000.0;
  return mssph::parse_scene(scene, "benchmark");
}

void BM_NeighbourSearch(benchmark::State& state) {
  const mssph::ParticleSetup setup = mssph::build_particles(block_scene("fluid", state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(mssph::reference::find_neighbours(setup.position, setup.smoothing_length));
  }
  state.counters["particles"] = static_cast<double>(setup.size());
}
BENCHMARK(BM_NeighbourSearch)->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_ReferenceStep(benchmark::State& state, const std::string& medium) {
  mssph::reference::ReferenceBackend backend(mssph::build_particles(block_scene(medium, state.range(0))));
  for (auto _ : state) backend.step();
  state.counters["particles"] = static_cast<double>(backend.particle_count());
}
BENCHMARK_CAPTURE(BM_ReferenceStep, fluid, std::string("fluid"))->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReferenceStep, rigid, std::string("rigid"))->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
