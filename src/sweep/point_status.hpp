#pragma once
// Where a point stands, read from its run log's root attribute `status`: what resume skips, what
// it reruns, and what it reports.
#include <string>

namespace mssph::sweep {

enum class PointState {
  missing,      // no log: never started
  completed,    // status "completed": done, skipped on resume
  failed,       // status "failed: <reason>" other than an interruption: rerun only with --retry-failed
  interrupted,  // status "interrupted..." or "failed: interrupted...": stopped by a signal, rerun
  incomplete    // anything else: "running" left by a killed process or node, or an unreadable file; rerun
};

struct PointStatus {
  PointState state = PointState::missing;
  std::string status;  // the attribute's text, or why the file could not be read
  // An interrupted or incomplete point whose partial log holds a checkpoint: it continues from
  // there (`mssph run --restart`) instead of starting over.
  bool continuable = false;
};

// Only a log whose status says "completed" counts as done: a partial log never does.
PointState classify_status(const std::string& status);
PointStatus read_point_status(const std::string& log_path);
const char* to_string(PointState state);

}  // namespace mssph::sweep
