#pragma once
// Test hooks: known slowdowns with which the comparison gate is tested. Never set them for real
// measurements (their values are recorded in the output's context).
// - MSSPH_BENCH_STEP_DELAY_US=N: every benchmarked step busy-waits N microseconds on the host after
//   the step: wall time only.
// - MSSPH_BENCH_EXTRA_STEP_EVERY=N: one extra step after every N benchmarked steps (or ticks): 1/N
//   more of the same work, which instruction counts see.
#include <cstddef>

namespace mssph::bench {

inline constexpr const char* kStepDelayVariable = "MSSPH_BENCH_STEP_DELAY_US";
inline constexpr const char* kExtraStepVariable = "MSSPH_BENCH_EXTRA_STEP_EVERY";

// N from the environment; 0 (no extra steps) when unset. A value that is not a positive integer is
// an InputError.
std::size_t extra_step_interval();

// The delay from the environment [s]; 0 when unset. A value that is not a non-negative number
// is an InputError.
double step_delay_seconds();

// Busy-waits (not sleeps: a sleeping thread's wake-up adds scheduler noise) for `seconds`.
void busy_wait(double seconds);

}  // namespace mssph::bench
