#pragma once
// One HDF5 file per run (docs/run-log.md). Root attributes say what ran and how it ended
// (`status`: "running", then "completed", "failed: <reason>" or "interrupted: <reason>"); every
// dataset has `units` and `description` attributes. Optional particle snapshots get an XDMF
// sidecar (<file>.xdmf) that ParaView opens.
//
// <path> holds a completed log or nothing: the log is written under <path>.partial (locked, see
// io/output_claim.hpp) and renamed to <path> by finish_completed() once whole and synced. A run
// that fails or is interrupted leaves its log at <path>.partial with its status saying why; a
// run killed at any moment leaves <path>.partial readable with status "running": rows are
// buffered in memory and reach the file only through flush() (called by the driver every few
// seconds and whenever a buffer fills), and a change of the file's structure (a new series,
// array or attribute) is flushed before the next row is buffered. Rows appended since the last
// flush are what such a kill loses.
//
// Checkpoints (io/checkpoint_io.hpp) make such a log continuable: write_checkpoint() stores the
// run's whole state, and a RunLog reopened for a restart cuts every series back to its rows at
// the latest checkpoint as the driver registers it again (add_series), removes the snapshots
// taken after it, and appends from there. A reopened log is read only until its first flush,
// which comes after the driver has set the run up again and restored the checkpoint: until then
// its changes (status, `restarts`, attributes, the cuts) wait in memory, so that a restart
// refused or failed before its first step leaves the file as it was, byte for byte.
//
// The sidecars are written whole (io/output_file.hpp): <path>.partial.xdmf while the log is
// unfinished, <path>.xdmf once it is published.
#include "io/checkpoint_io.hpp"
#include "io/output_claim.hpp"
#include "io/output_file.hpp"
#include "util/hdf5_handle.hpp"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace mssph {

struct RunMetadata {
  std::string version;
  std::string git_commit;
  std::string backend;
  std::string device;
  std::string precision;
  std::string scene_name;
  std::string config_path;
  std::string config_json;  // the scene after overrides: what the run used
  std::string config_file;  // the scene file's text, verbatim
  long long seed = 0;
  std::string command_line;
};

// Particle fields of one snapshot, in particle order (float32: what a viewer needs).
struct SnapshotFields {
  std::span<const float> position;  // 3 per particle [m]
  std::span<const float> velocity;  // 3 per particle [m/s]
  std::span<const float> density;   // [kg/m^3]
  std::span<const float> pressure;  // [Pa]
};

// What a restart takes from an earlier run's log (root attributes), so that it continues the
// same run: the scene as it ran (after --set), the backend and the run's options.
struct RunLogHeader {
  std::string config;       // the scene document (JSON)
  std::string config_path;  // the scene file it came from (locates a recorded trajectory)
  std::string backend;
  std::string record_device;      // "" for none
  std::string working_directory;  // where the run started, which relative paths above are from; "" when unknown
  bool phase_timing = false;
  double checkpoint_interval = 0.0;  // [s] wall clock; 0 for none
  long long checkpoint_step = -1;    // the step of the latest checkpoint, -1 when none is whole
};
// Throws InputError when `path` is no mssph run log.
RunLogHeader read_run_log_header(const std::string& path);

class RunLog {
 public:
  // Rows each series buffers before a full buffer flushes the file.
  static constexpr std::size_t kBufferedRows = 4096;
  // Disk space kept allocated beyond what is written, so that a full disk is noticed before a
  // write fails half-way and the log can still be closed with status "failed: disk full ...".
  static constexpr long long kReservedBytes = 1 << 20;

  // Creates the claimed output's partial file with the metadata and status "running".
  RunLog(OutputClaim claim, const RunMetadata& metadata);
  // Claims `path` first (replacing an existing regular file only when `replace`).
  RunLog(const std::string& path, const RunMetadata& metadata, bool replace = false);
  // Reopens the claimed partial file (OutputClaim::resume) to continue the run from its latest
  // checkpoint: status "running" again, `restart_command` added to the root's `restarts`, at the
  // first flush. Throws InputError, the file unchanged, when it is no run log, is completed, holds
  // no checkpoint, or a snapshot or the checkpoint cannot be read (damaged).
  struct Restart {
    std::string command_line;
  };
  RunLog(OutputClaim claim, const Restart& restart);
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  // Where the file is now: <path>.partial while the run lasts or after it failed, <path> once
  // completed.
  const std::string& path() const { return path_; }
  // Where a completed log goes.
  const std::string& final_path() const { return claim_.path(); }
  // Whether this process has changed the file: false for a reopened log until its first flush.
  bool changed() const { return writing_; }

  // A time series at `dataset_path` with `columns` values per row (a 1-D dataset when 1). Returns
  // its handle for append(). `column_names` (optional) become the `columns` attribute.
  std::size_t add_series(const std::string& dataset_path, std::size_t columns, const std::string& units,
                         const std::string& description, const std::vector<std::string>& column_names = {});
  void append(std::size_t series, std::span<const double> row);

  // Whole arrays written once, e.g. /particles/body (which snapshots then show as `body`).
  void write_array(const std::string& dataset_path, std::span<const int> values, const std::string& units,
                   const std::string& description);

  void set_attribute(const std::string& object_path, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object_path, const std::string& name, double value);
  void set_attribute(const std::string& object_path, const std::string& name, long long value);
  void set_attribute(const std::string& object_path, const std::string& name, const std::vector<std::string>& values);

  // /snapshots/<step, 8 digits> with attributes time and step; the XDMF sidecar is rewritten so
  // it always lists every snapshot written so far. Throws std::invalid_argument when the fields
  // disagree on the particle count.
  void add_snapshot(long long step, double time, const SnapshotFields& fields);

  // Writes buffered rows and asks HDF5 to flush the file to disk.
  void flush();

  // Stores the run's state after `step` steps (simulated time `time`) with every series' rows so
  // far; a restart continues from the latest.
  void write_checkpoint(long long step, double time, StateArrays state);
  // The checkpoint a reopened log continues from; nullptr for a new log.
  const Checkpoint* restart_point() const { return restart_ ? &*restart_ : nullptr; }

  // Final status; "completed" only for a run that reached its end. finish_completed() closes the
  // file and moves it (and its sidecar) to final_path(); it throws when that fails, leaving the
  // file at its partial name. A log without snapshots that replaced another (--force) removes the
  // replaced log's sidecar, which would name snapshots the new log lacks.
  void finish_completed();
  // "failed: <reason>" or "interrupted: <reason>", as far as the disk allows: these never throw
  // (the run's own failure is what gets reported), and the file stays at its partial name. A
  // reopened log not yet changed stays as it was.
  void finish_failed(const std::string& reason) noexcept;
  void finish_interrupted(const std::string& reason) noexcept;
  bool finished() const { return finished_; }

 private:
  struct Series {
    std::string path;
    std::size_t columns = 0;
    hsize_t rows_written = 0;
    std::vector<double> pending;  // rows not yet written, row-major
    h5::Handle dataset;
  };
  struct SnapshotRecord {
    long long step;
    double time;
    std::size_t particles;
    bool with_body;  // /particles/body holds one entry per particle of this snapshot
  };
  void write_pending(Series& series);
  // The XDMF text of the sidecar of the file at `h5_path`, which names its datasets.
  std::string xdmf_text(const std::string& h5_path) const;
  void set_status(const std::string& status);
  // Throws h5::Error "disk full writing <file>" when `bytes` (plus the reserve) would not fit.
  void ensure_space(long long bytes);
  void finish_unpublished(const std::string& status) noexcept;
  // After a restart, read only: lists the snapshots up to the checkpoint (for the sidecar) and
  // those after it (which start_writing() removes).
  void read_snapshots_up_to(long long step);
  // A reopened log's first change: reopens the file for writing and applies what waited.
  void start_writing();
  // Writes an attribute now, or once the file is written to (a reopened log before its flush).
  template <typename Value>
  void write_attribute_when_writing(const std::string& object_path, const std::string& name, const Value& value) {
    if (!writing_) {
      waiting_.push_back([this, object_path, name, value] { write_attribute_when_writing(object_path, name, value); });
      return;
    }
    h5::write_attribute(h5::open_or_create_group(file_.id(), object_path).id(), name, value);
    structure_changed_ = true;
  }

  OutputClaim claim_;  // declared before file_: the lock outlives the open file
  std::string path_;
  h5::Handle file_;
  std::vector<Series> series_;
  std::vector<SnapshotRecord> snapshots_;
  OutputFile partial_sidecar_;                  // <path>.partial.xdmf
  std::optional<Checkpoint> restart_;           // what a reopened log continues from
  std::string restart_command_;                 // the command line of the restart, for `restarts`
  std::vector<std::string> later_snapshots_;    // a reopened log's snapshots past its checkpoint
  std::vector<std::function<void()>> waiting_;  // a reopened log's attribute writes before its flush
  bool writing_ = true;                         // false for a reopened log until its first flush
  bool structure_changed_ = false;              // since the last flush
  bool finished_ = false;
};

}  // namespace mssph
