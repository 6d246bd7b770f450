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
  incomplete,   // anything else: "running" left by a killed process or node, or an unreadable file; rerun
  busy,         // another run is writing the log (it holds <log>.partial): not started, not counted
  foreign       // a log of another scene under the point's name (its `config` hashes otherwise): rerun
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
// The state of the point named `point_hash` (point_hash() of its scene) from its log at
// `log_path`: busy while another run holds the log, foreign when the scene the log records (its
// root attribute `config`) is not the point's, else what its status says.
PointStatus read_point_status(const std::string& log_path, const std::string& point_hash);
const char* to_string(PointState state);

}  // namespace mssph::sweep
