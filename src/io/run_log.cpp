#include "io/run_log.hpp"

#include "util/errors.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mssph {
namespace {

constexpr hsize_t kChunkRows = 1024;

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  std::ostringstream out;
  out << std::put_time(&tm, "%Y-%m-%dT%H:%M:%SZ");
  return out.str();
}

// Snapshots show each particle's body index when the driver has written it here.
constexpr const char* kBodyPath = "/particles/body";

// The five characters XML reserves, as entities.
std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string parent_path(const std::string& dataset_path) {
  const auto slash = dataset_path.find_last_of('/');
  return slash == 0 || slash == std::string::npos ? "/" : dataset_path.substr(0, slash);
}

std::string snapshot_group(long long step) {
  std::ostringstream name;
  name << "/snapshots/" << std::setw(8) << std::setfill('0') << step;
  return name.str();
}

void write_float_dataset(hid_t file, const std::string& path, std::span<const float> values, hsize_t columns,
                         const std::string& units, const std::string& description) {
  const hsize_t dims[2] = {values.size() / columns, columns};
  h5::Handle space = h5::dataspace(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), "snapshot space " + path);
  h5::Handle set =
      h5::dataset(H5Dcreate2(file, path.c_str(), H5T_IEEE_F32LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  "create " + path);
  h5::check(H5Dwrite(set.id(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + path);
  h5::write_attribute(set.id(), "units", units);
  h5::write_attribute(set.id(), "description", description);
}

// The claim's flock(2) on the partial file is the lock; HDF5's own lock on it would conflict.
h5::Handle unlocked_file_access() {
  h5::Handle access = h5::property_list(H5Pcreate(H5P_FILE_ACCESS), "file access properties");
  h5::check(H5Pset_file_locking(access.id(), false, true), "turn off HDF5 file locking");
  return access;
}

}  // namespace

RunLogHeader read_run_log_header(const std::string& path) {
  h5::silence_error_printing();
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, unlocked_file_access().id());
  if (file < 0) throw InputError("--restart " + path + ": not an HDF5 file this build can open");
  const h5::Handle owner = h5::file(file, "open " + path);
  for (const char* name :
       {"config", "config_path", "backend", "record_device", "phase_timing", "checkpoint_interval"}) {
    if (H5Aexists(file, name) <= 0) {
      throw InputError("--restart " + path + ": not a run log this version can continue (no root attribute " + name +
                       ")");
    }
  }
  RunLogHeader header;
  header.config = h5::read_string_attribute(file, "config");
  header.config_path = h5::read_string_attribute(file, "config_path");
  header.backend = h5::read_string_attribute(file, "backend");
  header.record_device = h5::read_string_attribute(file, "record_device");
  // Logs written before the attribute existed: their relative paths are taken as they are.
  if (H5Aexists(file, "working_directory") > 0) {
    header.working_directory = h5::read_string_attribute(file, "working_directory");
  }
  header.phase_timing = h5::read_double_attribute(file, "phase_timing") != 0.0;
  header.checkpoint_interval = h5::read_double_attribute(file, "checkpoint_interval");
  header.checkpoint_step = latest_checkpoint_step(file);
  return header;
}

RunLog::RunLog(const std::string& path, const RunMetadata& metadata, bool replace)
    : RunLog(OutputClaim(path, replace), metadata) {}

RunLog::RunLog(OutputClaim claim, const RunMetadata& metadata)
    : claim_(std::move(claim)),
      path_(claim_.partial_path()),
      partial_sidecar_(path_ + ".xdmf", claim_.replaces(), /*durable=*/false) {
  h5::silence_error_printing();
  // The default (oldest compatible) file format matters: it has no "open for writing" flag, which
  // newer formats leave set in a killed run's file, making readers refuse it until h5clear is run.
  file_ =
      h5::file(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, unlocked_file_access().id()), "create " + path_);
  const hid_t root = file_.id();
  h5::write_attribute(root, "mssph_version", metadata.version);
  h5::write_attribute(root, "git_commit", metadata.git_commit);
  h5::write_attribute(root, "backend", metadata.backend);
  h5::write_attribute(root, "device", metadata.device);
  h5::write_attribute(root, "precision", metadata.precision);
  h5::write_attribute(root, "scene", metadata.scene_name);
  h5::write_attribute(root, "config_path", metadata.config_path);
  h5::write_attribute(root, "config", metadata.config_json);
  h5::write_attribute(root, "config_file", metadata.config_file);
  h5::write_attribute(root, "seed", metadata.seed);
  h5::write_attribute(root, "command_line", metadata.command_line);
  h5::write_attribute(root, "start_time", utc_now());
  set_status("running");
  ensure_space(0);
  flush();
  // From here on the partial file is a readable log worth keeping, whatever happens to the run.
  claim_.keep_partial();
}

RunLog::RunLog(OutputClaim claim, const Restart& restart)
    : claim_(std::move(claim)),
      path_(claim_.partial_path()),
      // The sidecar of the log being continued, which its earlier process wrote.
      partial_sidecar_(path_ + ".xdmf", /*replace=*/true, /*durable=*/false),
      restart_command_(restart.command_line),
      writing_(false) {
  h5::silence_error_printing();
  const std::string head = "--restart " + path_ + ": ";
  const hid_t file = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, unlocked_file_access().id());
  if (file < 0) throw InputError(head + "not an HDF5 file this build can open");
  file_ = h5::file(file, "open " + path_);
  if (H5Aexists(file, "status") <= 0 || H5Aexists(file, "config") <= 0) throw InputError(head + "not an mssph run log");
  if (h5::read_string_attribute(file, "status") == "completed") throw InputError(head + "the run completed");
  try {
    restart_ = read_latest_checkpoint(file);
    if (restart_) read_snapshots_up_to(restart_->step);
  } catch (const h5::Error& e) {
    throw InputError(head + "damaged, cannot be continued (" + e.what() + ")");
  }
  if (!restart_) {
    throw InputError(head +
                     "holds no checkpoint to continue from (runs write one with --checkpoint-interval, and on "
                     "SIGINT, SIGTERM or SIGHUP)");
  }
}

void RunLog::read_snapshots_up_to(long long step) {
  if (!h5::object_exists(file_.id(), "/snapshots")) return;
  h5::Handle group = h5::group(H5Gopen2(file_.id(), "/snapshots", H5P_DEFAULT), "open /snapshots");
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  h5::check(H5Literate(group.id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names), "list /snapshots");
  for (const std::string& name : names) {
    const std::string path = "/snapshots/" + name;
    h5::Handle snapshot = h5::group(H5Gopen2(file_.id(), path.c_str(), H5P_DEFAULT), "open " + path);
    const auto snapshot_step = static_cast<long long>(h5::read_double_attribute(snapshot.id(), "step"));
    if (snapshot_step > step) {
      later_snapshots_.push_back(path);
      continue;
    }
    const std::size_t n = h5::dataset_shape(file_.id(), path + "/density").front();
    const bool with_body =
        h5::object_exists(file_.id(), kBodyPath) && h5::dataset_shape(file_.id(), kBodyPath) == std::vector<hsize_t>{n};
    snapshots_.push_back({snapshot_step, h5::read_double_attribute(snapshot.id(), "time"), n, with_body});
  }
}

void RunLog::start_writing() {
  if (writing_) return;
  // Every handle on the read-only file goes before the file is opened again for writing.
  for (Series& s : series_) s.dataset.reset();
  file_.reset();
  ensure_space(0);
  file_ = h5::file(H5Fopen(path_.c_str(), H5F_ACC_RDWR, unlocked_file_access().id()), "open " + path_);
  writing_ = true;
  const hid_t file = file_.id();
  std::string restarts = H5Aexists(file, "restarts") > 0 ? h5::read_string_attribute(file, "restarts") : "";
  restarts += "step " + std::to_string(restart_->step) + " at " + utc_now() + ": " + restart_command_ + "\n";
  h5::write_attribute(file, "restarts", restarts);
  set_status("running");
  for (const std::string& path : later_snapshots_)
    h5::check(H5Ldelete(file, path.c_str(), H5P_DEFAULT), "remove " + path);
  later_snapshots_.clear();
  for (const auto& write : waiting_) write();
  waiting_.clear();
  // Each series cut back to its rows at the checkpoint, appended from there.
  for (Series& s : series_) {
    s.dataset = h5::dataset(H5Dopen2(file, s.path.c_str(), H5P_DEFAULT), "open " + s.path);
    const hsize_t size[2] = {s.rows_written, s.columns};
    h5::check(H5Dset_extent(s.dataset.id(), size), "cut back " + s.path);
  }
  if (!snapshots_.empty()) partial_sidecar_.write(xdmf_text(path_));
  structure_changed_ = true;
}

RunLog::~RunLog() {
  // A log destroyed without finish_*() keeps status "running": whoever reads it knows the run
  // did not end normally. Pending rows are still written so nothing logged is lost; a reopened
  // log that was never written to stays as it was.
  if (!file_ || !writing_) return;
  try {
    flush();
  } catch (const std::exception&) {
    // A destructor must not throw; the file's status already tells the story.
  }
}

std::size_t RunLog::add_series(const std::string& dataset_path, std::size_t columns, const std::string& units,
                               const std::string& description, const std::vector<std::string>& column_names) {
  if (!writing_ && !h5::object_exists(file_.id(), dataset_path)) {
    throw InputError("--restart " + path_ + ": no " + dataset_path +
                     ", which the scene logs: the log is of another scene");
  }
  if (writing_) h5::open_or_create_group(file_.id(), parent_path(dataset_path));
  const int rank = columns == 1 ? 1 : 2;
  const hsize_t initial[2] = {0, columns};
  const hsize_t maximum[2] = {H5S_UNLIMITED, columns};
  const hsize_t chunk[2] = {kChunkRows, columns};
  h5::Handle space = h5::dataspace(H5Screate_simple(rank, initial, maximum), "series space " + dataset_path);
  h5::Handle properties = h5::property_list(H5Pcreate(H5P_DATASET_CREATE), "dataset properties");
  h5::check(H5Pset_chunk(properties.id(), rank, chunk), "chunk " + dataset_path);
  Series series;
  series.path = dataset_path;
  series.columns = columns;
  if (restart_ && h5::object_exists(file_.id(), dataset_path)) {
    // A restarted run's series: appended from its rows at the checkpoint (start_writing() cuts it
    // back to them).
    const auto rows = restart_->series_rows.find(dataset_path);
    if (rows == restart_->series_rows.end() ||
        h5::dataset_shape(file_.id(), dataset_path).size() != static_cast<std::size_t>(rank) ||
        (rank == 2 && h5::dataset_shape(file_.id(), dataset_path)[1] != columns)) {
      throw InputError("--restart " + path_ + ": " + dataset_path + " does not match the checkpoint or the scene");
    }
    series.dataset = h5::dataset(H5Dopen2(file_.id(), dataset_path.c_str(), H5P_DEFAULT), "open " + dataset_path);
    series.rows_written = rows->second;
    if (writing_) {
      const hsize_t size[2] = {rows->second, columns};
      h5::check(H5Dset_extent(series.dataset.id(), size), "cut back " + dataset_path);
    }
    series_.push_back(std::move(series));
    structure_changed_ = true;
    return series_.size() - 1;
  }
  series.dataset = h5::dataset(H5Dcreate2(file_.id(), dataset_path.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT,
                                          properties.id(), H5P_DEFAULT),
                               "create " + dataset_path);
  h5::write_attribute(series.dataset.id(), "units", units);
  h5::write_attribute(series.dataset.id(), "description", description);
  if (!column_names.empty()) h5::write_attribute(series.dataset.id(), "columns", column_names);
  series_.push_back(std::move(series));
  structure_changed_ = true;
  return series_.size() - 1;
}

void RunLog::append(std::size_t series, std::span<const double> row) {
  Series& s = series_.at(series);
  if (row.size() != s.columns) {
    throw std::invalid_argument("row of " + std::to_string(row.size()) + " values for " + s.path + " (" +
                                std::to_string(s.columns) + " columns)");
  }
  // A killed run's file must list every series even before its first periodic flush.
  if (structure_changed_) flush();
  s.pending.insert(s.pending.end(), row.begin(), row.end());
  // A full buffer flushes every series, not just this one: the file then stays consistent on
  // disk (no half-applied extension) and the series stay row-aligned.
  if (s.pending.size() >= kBufferedRows * s.columns) flush();
}

void RunLog::write_pending(Series& s) {
  const hsize_t rows = s.pending.size() / s.columns;
  if (rows == 0) return;
  const int rank = s.columns == 1 ? 1 : 2;
  const hsize_t new_size[2] = {s.rows_written + rows, s.columns};
  h5::check(H5Dset_extent(s.dataset.id(), new_size), "extend " + s.path);
  h5::Handle file_space = h5::dataspace(H5Dget_space(s.dataset.id()), "space of " + s.path);
  const hsize_t start[2] = {s.rows_written, 0};
  const hsize_t count[2] = {rows, s.columns};
  h5::check(H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start, nullptr, count, nullptr), "select " + s.path);
  h5::Handle memory_space = h5::dataspace(H5Screate_simple(rank, count, nullptr), "memory space");
  h5::check(
      H5Dwrite(s.dataset.id(), H5T_NATIVE_DOUBLE, memory_space.id(), file_space.id(), H5P_DEFAULT, s.pending.data()),
      "append to " + s.path);
  s.rows_written += rows;
  s.pending.clear();
}

void RunLog::write_array(const std::string& dataset_path, std::span<const int> values, const std::string& units,
                         const std::string& description) {
  if (!writing_ && !h5::object_exists(file_.id(), dataset_path)) {
    throw InputError("--restart " + path_ + ": no " + dataset_path +
                     ", which the scene writes: the log is of another scene");
  }
  if (writing_) h5::open_or_create_group(file_.id(), parent_path(dataset_path));
  const hsize_t dims[1] = {values.size()};
  if (restart_ && h5::object_exists(file_.id(), dataset_path)) {
    // A restarted run writes the same array again: it must be the one already there.
    if (h5::dataset_shape(file_.id(), dataset_path) != std::vector<hsize_t>{values.size()}) {
      throw InputError("--restart " + path_ + ": " + dataset_path + " does not match the scene");
    }
    return;
  }
  h5::Handle space = h5::dataspace(H5Screate_simple(1, dims, nullptr), "array space " + dataset_path);
  h5::Handle set = h5::dataset(
      H5Dcreate2(file_.id(), dataset_path.c_str(), H5T_STD_I32LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      "create " + dataset_path);
  h5::check(H5Dwrite(set.id(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + dataset_path);
  h5::write_attribute(set.id(), "units", units);
  h5::write_attribute(set.id(), "description", description);
  structure_changed_ = true;
}

void RunLog::set_attribute(const std::string& object_path, const std::string& name, const std::string& value) {
  write_attribute_when_writing(object_path, name, value);
}
void RunLog::set_attribute(const std::string& object_path, const std::string& name, double value) {
  write_attribute_when_writing(object_path, name, value);
}
void RunLog::set_attribute(const std::string& object_path, const std::string& name, long long value) {
  write_attribute_when_writing(object_path, name, value);
}
void RunLog::set_attribute(const std::string& object_path, const std::string& name,
                           const std::vector<std::string>& values) {
  write_attribute_when_writing(object_path, name, values);
}

void RunLog::add_snapshot(long long step, double time, const SnapshotFields& fields) {
  const std::size_t n = fields.density.size();
  if (fields.position.size() != 3 * n || fields.velocity.size() != 3 * n || fields.pressure.size() != n) {
    throw std::invalid_argument("snapshot of step " + std::to_string(step) + ": " + std::to_string(n) +
                                " densities but " + std::to_string(fields.position.size()) + " position, " +
                                std::to_string(fields.velocity.size()) + " velocity and " +
                                std::to_string(fields.pressure.size()) + " pressure values");
  }
  start_writing();
  ensure_space(static_cast<long long>(n * 8 * sizeof(float)));
  const std::string group_path = snapshot_group(step);
  h5::Handle group = h5::open_or_create_group(file_.id(), group_path);
  h5::write_attribute(group.id(), "time", time);
  h5::write_attribute(group.id(), "step", step);
  write_float_dataset(file_.id(), group_path + "/position", fields.position, 3, "m", "particle positions (x, y, z)");
  write_float_dataset(file_.id(), group_path + "/velocity", fields.velocity, 3, "m/s", "particle velocities (x, y, z)");
  write_float_dataset(file_.id(), group_path + "/density", fields.density, 1, "kg/m^3", "SPH density of each particle");
  write_float_dataset(file_.id(), group_path + "/pressure", fields.pressure, 1, "Pa",
                      "pressure of each particle, P = k (rho - rho0)");
  const bool with_body =
      h5::object_exists(file_.id(), kBodyPath) && h5::dataset_shape(file_.id(), kBodyPath) == std::vector<hsize_t>{n};
  snapshots_.push_back({step, time, n, with_body});
  flush();
  partial_sidecar_.write(xdmf_text(path_));
}

// XDMF 3: a temporal collection of polyvertex grids whose heavy data are the HDF5 datasets,
// named relative to the sidecar, which lies next to the HDF5 file.
std::string RunLog::xdmf_text(const std::string& h5_path) const {
  const std::string h5_name = xml_escape(std::filesystem::path(h5_path).filename().string());
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotRecord& s : snapshots_) {
    const std::string group = snapshot_group(s.step);
    const std::string n = std::to_string(s.particles);
    const auto item = [&](const std::string& path, bool vector, const char* type) {
      return "<DataItem Dimensions=\"" + n + (vector ? " 3" : "") + "\" NumberType=\"" + type +
             "\" Precision=\"4\" Format=\"HDF\">" + h5_name + ":" + path + "</DataItem>";
    };
    const auto attribute = [&](const char* name, bool vector, const std::string& data_item) {
      return std::string("    <Attribute Name=\"") + name + "\" AttributeType=\"" + (vector ? "Vector" : "Scalar") +
             "\" Center=\"Node\">" + data_item + "</Attribute>\n";
    };
    out << "   <Grid Name=\"step" << s.step << "\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << std::setprecision(17) << s.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n"
        << "    <Geometry GeometryType=\"XYZ\">" << item(group + "/position", true, "Float") << "</Geometry>\n"
        << attribute("velocity", true, item(group + "/velocity", true, "Float"))
        << attribute("density", false, item(group + "/density", false, "Float"))
        << attribute("pressure", false, item(group + "/pressure", false, "Float"));
    if (s.with_body) out << attribute("body", false, item(kBodyPath, false, "Int"));
    out << "   </Grid>\n";
  }
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return out.str();
}

void RunLog::ensure_space(long long bytes) {
  const int error = claim_.reserve(bytes + kReservedBytes);
  if (error == 0) return;
  throw h5::Error(std::string(error == ENOSPC ? "disk full" : "file size limit (ulimit -f) reached") + " writing " +
                      path_ + " (" + std::to_string(bytes + kReservedBytes) +
                      " bytes more would not fit; the log is closed while it still can be)",
                  error);
}

void RunLog::flush() {
  start_writing();
  long long pending_bytes = 0;
  for (const Series& s : series_) pending_bytes += static_cast<long long>(s.pending.size() * sizeof(double));
  ensure_space(pending_bytes);
  for (Series& s : series_) write_pending(s);
  h5::check(H5Fflush(file_.id(), H5F_SCOPE_GLOBAL), "flush " + path_);
  structure_changed_ = false;
}

void RunLog::write_checkpoint(long long step, double time, StateArrays state) {
  flush();
  ensure_space(state_bytes(state));
  Checkpoint checkpoint{step, time, std::move(state), {}};
  for (const Series& s : series_) checkpoint.series_rows[s.path] = s.rows_written;
  mssph::write_checkpoint(file_.id(), checkpoint);
}

void RunLog::set_status(const std::string& status) { h5::write_attribute(file_.id(), "status", status); }

void RunLog::finish_completed() {
  start_writing();
  h5::write_attribute(file_.id(), "end_time", utc_now());
  set_status("completed");
  flush();
  file_.reset();
  finished_ = true;
  // The sidecar first, so that the moment the log appears at its final path, its sidecar does.
  const std::string final_xdmf = final_path() + ".xdmf";
  if (!snapshots_.empty()) {
    OutputFile(final_xdmf, claim_.replaces()).write(xdmf_text(final_path()));
  } else if (claim_.replaces()) {
    // A replaced log's sidecar would name snapshots the new log lacks (a regular file only, as
    // --force allows).
    struct stat st {};
    if (lstat(final_xdmf.c_str(), &st) == 0 && S_ISREG(st.st_mode)) unlink(final_xdmf.c_str());
  }
  claim_.publish();
  path_ = final_path();
  partial_sidecar_.remove_written();
}

void RunLog::finish_unpublished(const std::string& status) noexcept {
  if (!file_) return;
  if (!writing_) {
    // A reopened log whose run ended before its first flush: left as it was.
    file_.reset();
    finished_ = true;
    return;
  }
  try {
    h5::write_attribute(file_.id(), "end_time", utc_now());
    set_status(status);
    // Into the reserved space when the disk is full: no ensure_space() here.
    for (Series& s : series_) write_pending(s);
    h5::check(H5Fflush(file_.id(), H5F_SCOPE_GLOBAL), "flush " + path_);
  } catch (const std::exception&) {
    // The disk may be full or failing: what could be written is, and the caller reports why.
  }
  file_.reset();
  finished_ = true;
}

void RunLog::finish_failed(const std::string& reason) noexcept { finish_unpublished("failed: " + reason); }

void RunLog::finish_interrupted(const std::string& reason) noexcept { finish_unpublished("interrupted: " + reason); }

}  // namespace mssph
