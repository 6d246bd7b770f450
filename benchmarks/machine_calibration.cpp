#include "machine_calibration.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

namespace mssph::bench {
namespace {

// What the workload is made of: points in a unit box and, for each, partners to gather, both
// drawn once from fixed seeds. The code below must never change, or baselines that hold its times
// no longer measure the same work; it uses nothing of mssph, so that no change to mssph moves it.
struct CalibrationSet {
  static constexpr std::size_t kPoints = 4096;
  static constexpr std::size_t kPartners = 64;
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> partner;  // kPartners per point
};

CalibrationSet make_calibration_set() {
  CalibrationSet set;
  std::mt19937 random(20111024);
  std::uniform_real_distribution<float> coordinate(0.0f, 1.0f);
  for (std::size_t i = 0; i < CalibrationSet::kPoints; ++i) {
    set.x.push_back(coordinate(random));
    set.y.push_back(coordinate(random));
    set.z.push_back(coordinate(random));
  }
  std::uniform_int_distribution<std::uint32_t> any(0, CalibrationSet::kPoints - 1);
  for (std::size_t k = 0; k < CalibrationSet::kPoints * CalibrationSet::kPartners; ++k)
    set.partner.push_back(any(random));
  return set;
}

// A neighbour sum's kind of work: gathered loads and float arithmetic, (h^2 - r^2)^3 summed over
// each point's partners within h (about 28 % of them at h = 0.5).
float gather_sums(const CalibrationSet& set) {
  constexpr float h2 = 0.25f;
  float total = 0.0f;
  for (std::size_t i = 0; i < CalibrationSet::kPoints; ++i) {
    float sum = 0.0f;
    for (std::size_t k = 0; k < CalibrationSet::kPartners; ++k) {
      const std::uint32_t j = set.partner[i * CalibrationSet::kPartners + k];
      const float dx = set.x[i] - set.x[j], dy = set.y[i] - set.y[j], dz = set.z[i] - set.z[j];
      const float q = h2 - (dx * dx + dy * dy + dz * dz);
      sum += q > 0.0f ? q * q * q : 0.0f;
    }
    total += sum;
  }
  return total;
}

void time_calibration(benchmark::State& state) {
  const CalibrationSet set = make_calibration_set();
  for (auto _ : state) benchmark::DoNotOptimize(gather_sums(set));
}

}  // namespace

void register_calibration() {
  benchmark::RegisterBenchmark(kCalibrationBenchmark, time_calibration)->Unit(benchmark::kMicrosecond);
}

}  // namespace mssph::bench
