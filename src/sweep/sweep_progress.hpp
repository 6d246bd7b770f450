#pragma once
// Progress of a sweep on stderr: one line per point that starts or ends, and a reminder line when
// nothing has happened for a while, each with the counts (done, running, failed) and an ETA from
// the mean duration of the points finished so far.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace mssph::sweep {

struct SweepCounts {
  std::size_t total = 0;   // points this invocation is responsible for (its shard)
  std::size_t done = 0;    // completed, now or before
  std::size_t failed = 0;  // failed, now or before (not retried)
  std::size_t running = 0;
  std::size_t interrupted = 0;  // stopped this time; rerun by the next invocation
};

// Seconds left: the points still to run, in waves of `parallel`, each as long as the mean point
// finished so far. nullopt before any point has finished.
std::optional<double> eta_seconds(std::size_t points_left, std::size_t parallel, std::size_t finished_points,
                                  double finished_seconds);

class SweepProgress {
 public:
  SweepProgress(std::string sweep_name, SweepCounts counts, std::size_t parallel);

  SweepCounts& counts() { return counts_; }
  void started(const std::string& what);
  // A point ended after `seconds`: completed or not, it counts towards the ETA.
  void finished(const std::string& what, double seconds);
  void note(const std::string& line);  // a line without counts
  // A reminder line when nothing was printed for a minute.
  void tick();

 private:
  void print(const std::string& event);
  using Clock = std::chrono::steady_clock;
  std::string name_;
  SweepCounts counts_;
  std::size_t parallel_;
  std::size_t finished_points_ = 0;
  double finished_seconds_ = 0.0;
  Clock::time_point last_print_ = Clock::now();
};

}  // namespace mssph::sweep
