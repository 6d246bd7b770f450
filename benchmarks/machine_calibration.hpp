#pragma once
// calibration/cpu: a fixed workload that times the machine rather than mssph, so that
// `mssph bench compare --normalize-by calibration/cpu` can divide out how fast the machine ran
// each file (a shared CI VM runs the same build at different speeds at different hours;
// results/baselines/ci-2core/README.md).
namespace mssph::bench {

inline constexpr const char* kCalibrationBenchmark = "calibration/cpu";

// Registers calibration/cpu.
void register_calibration();

}  // namespace mssph::bench
