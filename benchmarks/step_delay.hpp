#pragma once
// Test hook: MSSPH_BENCH_STEP_DELAY_US=N makes every benchmarked step busy-wait N microseconds
// on the host after the step, a known slowdown with which the comparison gate is tested. Never
// set it for real measurements (its value is recorded in the output's context).
namespace mssph::bench {

inline constexpr const char* kStepDelayVariable = "MSSPH_BENCH_STEP_DELAY_US";

// The delay from the environment [s]; 0 when unset. A value that is not a non-negative number
// is an InputError.
double step_delay_seconds();

// Busy-waits (not sleeps: a sleeping thread's wake-up adds scheduler noise) for `seconds`.
void busy_wait(double seconds);

}  // namespace mssph::bench
