#include "progress.hpp"

#include <cstdio>

namespace mssph {
namespace {

constexpr double kFirstReportAfter = 3.0;  // [s] short runs print nothing
constexpr double kReportEvery = 5.0;       // [s]

}  // namespace

ProgressReporter::ProgressReporter(std::size_t total_steps, double dt, bool quiet, std::size_t first_step)
    : total_steps_(total_steps),
      first_step_(first_step),
      dt_(dt),
      quiet_(quiet),
      start_(Clock::now()),
      last_print_(start_) {}

void ProgressReporter::update(std::size_t steps_done) {
  if (quiet_ || steps_done <= first_step_) return;
  const Clock::time_point now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double since_print = std::chrono::duration<double>(now - last_print_).count();
  const bool first = last_print_ == start_;
  if (elapsed < kFirstReportAfter || (!first && since_print < kReportEvery)) return;
  last_print_ = now;
  const double rate = static_cast<double>(steps_done - first_step_) / elapsed;
  const double eta = static_cast<double>(total_steps_ - steps_done) / rate;
  std::fprintf(stderr, "  step %zu/%zu  t = %.4f/%.4f s  %.1f steps/s  ETA %.0f s\n", steps_done, total_steps_,
               static_cast<double>(steps_done) * dt_, static_cast<double>(total_steps_) * dt_, rate, eta);
}

}  // namespace mssph
