#pragma once
// Runs sweep points as child processes, each an ordinary `mssph run` with its own log, several at
// once: one per slot (a --jobs slot, or a GPU of --gpus with CUDA_VISIBLE_DEVICES set to it),
// points handed out in order as slots free up.
//
// SIGINT or SIGTERM to the sweep: no new point starts, the signal is passed on to the running
// ones (which end after their current step, their logs marked interrupted) and the runner returns
// once they have exited. A sweep killed outright (SIGKILL, a node lost) takes its children with
// it: each is started with SIGTERM as its parent-death signal, so no point keeps running orphaned
// and every point in flight is left incomplete, to be rerun.
#include "sweep/point_status.hpp"
#include "sweep/sweep_progress.hpp"

#include <string>
#include <vector>

namespace mssph::sweep {

struct PointTask {
  std::string label;              // how progress names the point
  std::vector<std::string> argv;  // argv[0] is the program's path
  std::string log_path;           // the run log the child writes
  std::string point_hash;         // the point's name, which its log's scene must hash to
  std::string output_path;        // the child's stdout and stderr
};

struct RunSlot {
  std::string label;                     // "job 1", "GPU 0"
  std::vector<std::string> environment;  // NAME=VALUE set for every child started in this slot
};

struct RunnerReport {
  std::size_t completed = 0;
  std::size_t failed = 0;
  std::size_t interrupted = 0;     // stopped by a signal, or left incomplete
  bool stopped_by_signal = false;  // the sweep itself got SIGINT or SIGTERM
  std::string bad_input;           // a child exited with code 2: why (the sweep then stops)
};

RunnerReport run_point_tasks(const std::vector<PointTask>& tasks, const std::vector<RunSlot>& slots,
                             SweepProgress& progress);

// The last `lines` lines of a text file ("" when it cannot be read), to show why a point failed.
std::string tail_of_file(const std::string& path, std::size_t lines);

}  // namespace mssph::sweep
