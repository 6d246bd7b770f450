#include "io/checkpoint_io.hpp"

#include <algorithm>
#include <sstream>

namespace mssph {
namespace {

constexpr const char* kSlots[2] = {"/checkpoint/a", "/checkpoint/b"};
constexpr long long kWriting = -1;

template <class T>
hid_t file_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_IEEE_F64LE;
  if constexpr (std::is_same_v<T, float>) return H5T_IEEE_F32LE;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_STD_I64LE;
  return H5T_STD_U8LE;
}
template <class T>
hid_t memory_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same_v<T, float>) return H5T_NATIVE_FLOAT;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  return H5T_NATIVE_UINT8;
}

std::string parent_of(const std::string& path) { return path.substr(0, path.find_last_of('/')); }

// A 1-D extendible dataset at `path` holding `values`, created on the slot's first use (with the
// `units` and `description` every dataset of a log carries) and resized in place afterwards, so
// that rewriting a slot reuses its file space.
template <class T>
void write_array(hid_t file, const std::string& path, const std::vector<T>& values, const std::string& units,
                 const std::string& description) {
  const hsize_t size[1] = {values.size()};
  h5::Handle set;
  if (h5::object_exists(file, path)) {
    set = h5::dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open " + path);
    h5::check(H5Dset_extent(set.id(), size), "resize " + path);
  } else {
    h5::open_or_create_group(file, parent_of(path));
    const hsize_t maximum[1] = {H5S_UNLIMITED};
    const hsize_t chunk[1] = {std::clamp<hsize_t>(values.size(), 1, hsize_t{1} << 16)};
    h5::Handle space = h5::dataspace(H5Screate_simple(1, size, maximum), "space of " + path);
    h5::Handle properties = h5::property_list(H5Pcreate(H5P_DATASET_CREATE), "dataset properties");
    h5::check(H5Pset_chunk(properties.id(), 1, chunk), "chunk " + path);
    set = h5::dataset(
        H5Dcreate2(file, path.c_str(), file_type<T>(), space.id(), H5P_DEFAULT, properties.id(), H5P_DEFAULT),
        "create " + path);
    h5::write_attribute(set.id(), "units", units);
    h5::write_attribute(set.id(), "description", description);
  }
  if (!values.empty()) {
    h5::check(H5Dwrite(set.id(), memory_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + path);
  }
}

template <class T>
std::vector<T> read_array(hid_t set, const std::string& path) {
  h5::Handle space = h5::dataspace(H5Dget_space(set), "space of " + path);
  const hssize_t count = H5Sget_simple_extent_npoints(space.id());
  if (count < 0) h5::throw_error("size of " + path);
  std::vector<T> values(static_cast<std::size_t>(count));
  if (!values.empty())
    h5::check(H5Dread(set, memory_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + path);
  return values;
}

// The element type of a checkpoint dataset, as written by write_array.
StateArrays::Array read_state_array(hid_t set, const std::string& path) {
  h5::Handle type = h5::datatype(H5Dget_type(set), "type of " + path);
  const H5T_class_t type_class = H5Tget_class(type.id());
  const std::size_t size = H5Tget_size(type.id());
  if (type_class == H5T_FLOAT) {
    if (size == 8) return read_array<double>(set, path);
    return read_array<float>(set, path);
  }
  if (type_class == H5T_INTEGER && size == 8) return read_array<std::int64_t>(set, path);
  if (type_class == H5T_INTEGER && size == 1) return read_array<std::uint8_t>(set, path);
  throw h5::Error("checkpoint dataset " + path + " has a type no checkpoint writes", 0);
}

struct SlotReader {
  std::string root;  // the slot's state group, with a trailing '/'
  StateArrays* state;
};

herr_t read_slot_entry(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto* reader = static_cast<SlotReader*>(data);
  h5::Handle object(H5Oopen(group, name, H5P_DEFAULT), H5Oclose, std::string("open ") + name);
  if (H5Iget_type(object.id()) != H5I_DATASET) return 0;
  reader->state->set(name, read_state_array(object.id(), reader->root + name));
  return 0;
}

long long slot_step(hid_t file, const char* slot) {
  if (!h5::object_exists(file, slot)) return kWriting;
  h5::Handle group = h5::group(H5Gopen2(file, slot, H5P_DEFAULT), std::string("open ") + slot);
  if (H5Aexists(group.id(), "step") <= 0) return kWriting;
  return static_cast<long long>(h5::read_double_attribute(group.id(), "step"));
}

}  // namespace

long long state_bytes(const StateArrays& state) {
  long long bytes = 0;
  for (const auto& [name, values] : state.arrays()) {
    std::visit([&](const auto& v) { bytes += static_cast<long long>(v.size() * sizeof(v.front())); }, values);
  }
  return bytes;
}

void write_checkpoint(hid_t file, const Checkpoint& checkpoint) {
  const int latest = slot_step(file, kSlots[1]) > slot_step(file, kSlots[0]) ? 1 : 0;
  const std::string slot = kSlots[1 - latest];
  h5::Handle group = h5::open_or_create_group(file, slot);
  h5::write_attribute(group.id(), "step", kWriting);
  h5::check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush before a checkpoint");
  for (const auto& [array_name, values] : checkpoint.state.arrays()) {
    const std::string& name = array_name;  // named again: Clang before 16 cannot capture a structured binding
    std::visit(
        [&](const auto& v) {
          write_array(
              file, slot + "/state/" + name, v, "SI, per quantity",
              "checkpoint array " + name +
                  ": part of the run's state at the slot's step, as the code that "
                  "saved it laid it out (src/backend/state_arrays.hpp); mssph run --restart restores it bit for bit");
        },
        values);
  }
  std::vector<std::int64_t> rows;
  std::string names;
  for (const auto& [path, count] : checkpoint.series_rows) {
    rows.push_back(static_cast<std::int64_t>(count));
    names += path + "\n";
  }
  write_array(file, slot + "/series_rows", rows, "1",
              "rows of each time series at the slot's step (attribute series names them, one per line)");
  h5::Handle table = h5::dataset(H5Dopen2(file, (slot + "/series_rows").c_str(), H5P_DEFAULT), "open series_rows");
  h5::write_attribute(table.id(), "series", names);
  h5::write_attribute(group.id(), "time", checkpoint.time);
  h5::check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush a checkpoint");
  h5::write_attribute(group.id(), "step", checkpoint.step);
  h5::check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush a checkpoint");
}

long long latest_checkpoint_step(hid_t file) {
  return std::max(slot_step(file, kSlots[0]), slot_step(file, kSlots[1]));
}

std::optional<Checkpoint> read_latest_checkpoint(hid_t file) {
  const long long steps[2] = {slot_step(file, kSlots[0]), slot_step(file, kSlots[1])};
  const int latest = steps[1] > steps[0] ? 1 : 0;
  if (steps[latest] == kWriting) return std::nullopt;
  const std::string slot = kSlots[latest];
  Checkpoint checkpoint;
  checkpoint.step = steps[latest];
  h5::Handle group = h5::group(H5Gopen2(file, slot.c_str(), H5P_DEFAULT), "open " + slot);
  checkpoint.time = h5::read_double_attribute(group.id(), "time");
  const std::string state_path = slot + "/state";
  if (h5::object_exists(file, state_path)) {
    h5::Handle state = h5::group(H5Gopen2(file, state_path.c_str(), H5P_DEFAULT), "open " + state_path);
    SlotReader reader{state_path + "/", &checkpoint.state};
    h5::check(H5Lvisit(state.id(), H5_INDEX_NAME, H5_ITER_INC, read_slot_entry, &reader), "read " + state_path);
  }
  const std::string table_path = slot + "/series_rows";
  h5::Handle table = h5::dataset(H5Dopen2(file, table_path.c_str(), H5P_DEFAULT), "open " + table_path);
  const std::vector<std::int64_t> rows = read_array<std::int64_t>(table.id(), table_path);
  std::istringstream names(h5::read_string_attribute(table.id(), "series"));
  std::string path;
  for (std::size_t k = 0; std::getline(names, path) && k < rows.size(); ++k) {
    checkpoint.series_rows[path] = static_cast<hsize_t>(rows[k]);
  }
  return checkpoint;
}

}  // namespace mssph
