#include "sweep/sweep_progress.hpp"

#include <cmath>
#include <cstdio>

namespace mssph::sweep {
namespace {

constexpr double kReminderEvery = 60.0;  // [s]

std::string format_duration(double seconds) {
  char text[32];
  if (seconds < 120.0) {
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  } else if (seconds < 7200.0) {
    std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
  }
  return text;
}

}  // namespace

std::optional<double> eta_seconds(std::size_t points_left, std::size_t parallel, std::size_t finished_points,
                                  double finished_seconds) {
  if (finished_points == 0 || parallel == 0) return std::nullopt;
  const double waves = std::ceil(static_cast<double>(points_left) / static_cast<double>(parallel));
  return waves * finished_seconds / static_cast<double>(finished_points);
}

SweepProgress::SweepProgress(std::string sweep_name, SweepCounts counts, std::size_t parallel)
    : name_(std::move(sweep_name)), counts_(counts), parallel_(parallel) {}

void SweepProgress::started(const std::string& what) { print(what + " started"); }

void SweepProgress::finished(const std::string& what, double seconds) {
  ++finished_points_;
  finished_seconds_ += seconds;
  print(what + " after " + format_duration(seconds));
}

void SweepProgress::note(const std::string& line) {
  std::fprintf(stderr, "sweep %s: %s\n", name_.c_str(), line.c_str());
  last_print_ = Clock::now();
}

void SweepProgress::tick() {
  if (std::chrono::duration<double>(Clock::now() - last_print_).count() >= kReminderEvery) print("still running");
}

void SweepProgress::print(const std::string& event) {
  const std::size_t left = counts_.total - counts_.done - counts_.failed - counts_.interrupted;
  // The points running now are part of what is left, started some time ago: a slight overestimate.
  const auto eta = eta_seconds(left, parallel_, finished_points_, finished_seconds_);
  std::fprintf(stderr, "sweep %s: %s  [%zu/%zu done, %zu running, %zu failed; ETA %s]\n", name_.c_str(), event.c_str(),
               counts_.done, counts_.total, counts_.running, counts_.failed,
               eta ? format_duration(*eta).c_str() : "after the first point");
  last_print_ = Clock::now();
}

}  // namespace mssph::sweep
