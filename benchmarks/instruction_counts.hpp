#pragma once
// Instructions executed per step, counted by Valgrind's Callgrind: a cost measure that other load
// on the machine cannot change, for gating on a shared CI runner. `mssph bench --count-instructions`
// runs the timed suite, then this program again under Callgrind, which counts each benchmark's
// workload between client requests (outside them it runs uninstrumented), and adds the counts to
// the benchmark file beside the times.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mssph::bench {

// One counted region: `units` repetitions of the unit of work a benchmark times (a step, a tick).
class CountedRegion {
 public:
  explicit CountedRegion(std::string name) : name_(std::move(name)) {}
  // Runs `unit` `units` times with Callgrind's instrumentation on and its counts dumped under the
  // region's name (a plain run when not under Valgrind).
  void measure(std::size_t units, const std::function<void()>& unit) const;

 private:
  std::string name_;
};

// A benchmark's workload as counted: it sets up and warms up as the timed benchmark does, then
// calls region.measure once.
using CountedWorkload = std::function<void(const CountedRegion& region)>;
void add_counted_workload(const std::string& name, CountedWorkload workload);

// Runs the counted workloads whose names match the regular expression (ECMAScript, searched).
// Returns how many ran.
std::size_t run_counted_workloads(const std::string& filter);

struct InstructionCount {
  std::string name;
  double instructions_per_unit = 0.0;  // Callgrind's Ir over the region, per step or tick
  double ll_misses_per_unit = 0.0;     // simulated last-level misses (ILmr + DLmr + DLmw) per unit
};

// Runs `program_arguments` (this program's own arguments for a counting run) under
// valgrind --tool=callgrind with its dumps in `work_dir`, and reads the counts. Throws
// std::runtime_error when Valgrind cannot be started or a dump is missing or malformed.
std::vector<InstructionCount> count_instructions(const std::vector<std::string>& program_arguments,
                                                 const std::string& work_dir);

// Adds instructions_per_step and ll_misses_per_step to every entry of the Google Benchmark JSON
// `path` whose run_name is a counted benchmark (with its /manual_time suffix or without), and
// records the counting settings in its context.
void add_counts_to_benchmark_file(const std::string& path, const std::vector<InstructionCount>& counts);

}  // namespace mssph::bench
