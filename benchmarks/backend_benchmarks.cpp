// The benchmark suite (benchmark_suite.hpp) as a plain Google Benchmark program: every flag of
// Google Benchmark applies, e.g. --benchmark_filter=step/cuda. `mssph bench` runs the same suite.
#include "benchmark_suite.hpp"

#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  mssph::bench::register_suite(mssph::bench::default_benchmark_backends());
  mssph::bench::add_machine_context();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
