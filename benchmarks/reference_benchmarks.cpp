// Google Benchmark timings of the double-precision reference: neighbour search and whole steps
// for blocks of each medium. The reference is the oracle, not the fast path; these numbers say
// how large a scene the validation suite can afford.
#include "model/block_scene.hpp"
#include "model/neighbour_search.hpp"
#include "model/scene_builder.hpp"
#include "reference_backend.hpp"

#include <benchmark/benchmark.h>

namespace {

void BM_NeighbourSearch(benchmark::State& state) {
  const mssph::ParticleSetup setup =
      mssph::build_particles(mssph::block_scene(mssph::BodyKind::fluid, static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    benchmark::DoNotOptimize(mssph::find_neighbours(setup.position, setup.smoothing_length));
  }
  state.counters["particles"] = static_cast<double>(setup.size());
}
BENCHMARK(BM_NeighbourSearch)->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_ReferenceStep(benchmark::State& state, mssph::BodyKind medium) {
  mssph::reference::ReferenceBackend backend(
      mssph::build_particles(mssph::block_scene(medium, static_cast<std::size_t>(state.range(0)))));
  for (auto _ : state) backend.step();
  state.counters["particles"] = static_cast<double>(backend.particle_count());
}
BENCHMARK_CAPTURE(BM_ReferenceStep, fluid, mssph::BodyKind::fluid)
    ->Arg(2000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReferenceStep, rigid, mssph::BodyKind::rigid)
    ->Arg(2000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReferenceStep, deformable, mssph::BodyKind::deformable)
    ->Arg(2000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
