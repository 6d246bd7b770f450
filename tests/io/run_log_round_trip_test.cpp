// Writes a run log through RunLog and reads every part of it back with the HDF5 C API.
#include "h5_read.hpp"
#include "io/run_log.hpp"
#include "run_log_samples.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace mssph::test {
namespace {

// More rows than one buffer holds, so the scalar series is written by several flushes, and a
// count that is not a multiple of the buffer, so the last flush writes a partial buffer.
constexpr std::size_t kScalarRows = 3 * RunLog::kBufferedRows + 17;
constexpr std::size_t kVectorRows = 2 * RunLog::kBufferedRows + 5;
constexpr std::size_t kParticles = 5;

struct SnapshotData {
  std::vector<float> position, velocity, density, pressure;
};

SnapshotData sample_snapshot() {
  SnapshotData s;
  for (std::size_t i = 0; i < kParticles; ++i) {
    const float x = static_cast<float>(i);
    s.position.insert(s.position.end(), {x, x + 0.25f, -x});
    s.velocity.insert(s.velocity.end(), {-x, 0.5f * x, 2.0f});
    s.density.push_back(1000.0f + x);
    s.pressure.push_back(10.0f * x - 3.0f);
  }
  return s;
}

const std::vector<int> kBodies{0, 0, 1, 1, 1};

void write_sample_log(const std::string& path) {
  RunLog log(path, sample_metadata());
  log.set_attribute("/", "warnings", std::string("dt exceeds the acoustic bound\n"));
  log.set_attribute("/bodies/ball", "mass", 4.1887902047863905);
  log.set_attribute("/bodies/ball", "particle_count", 3LL);
  log.set_attribute("/timing", "phase_names", std::vector<std::string>{"neighbours", "density", "forces"});
  log.set_attribute("/timing", "no_names", std::vector<std::string>{});
  log.write_array("/particles/body", kBodies, "1", "body index of each particle");
  const std::size_t scalar = log.add_series("/time", 1, "s", "simulated time");
  const std::size_t vector = log.add_series("/bodies/ball/centre_of_mass", 3, "m", "centre of mass", {"x", "y", "z"});
  for (std::size_t i = 0; i < kScalarRows; ++i) {
    const double v = scalar_row(i);
    log.append(scalar, std::span<const double>(&v, 1));
    if (i < kVectorRows) log.append(vector, vector_row(i));
  }
  const SnapshotData snap = sample_snapshot();
  log.add_snapshot(40, 0.02, SnapshotFields{snap.position, snap.velocity, snap.density, snap.pressure});
  log.finish_completed();
}

class RunLogRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (dir_ / "round_trip.h5").string();
    write_sample_log(path_);
    file_ = open_read_only(path_);
  }
  hid_t file() const { return file_.id(); }

  TempDir dir_;
  std::string path_;
  h5::Handle file_;
};

TEST_F(RunLogRoundTrip, RootAttributesHoldTheMetadata) {
  const RunMetadata m = sample_metadata();
  EXPECT_EQ(h5::read_string_attribute(file(), "mssph_version"), m.version);
  EXPECT_EQ(h5::read_string_attribute(file(), "git_commit"), m.git_commit);
  EXPECT_EQ(h5::read_string_attribute(file(), "backend"), m.backend);
  EXPECT_EQ(h5::read_string_attribute(file(), "device"), m.device);
  EXPECT_EQ(h5::read_string_attribute(file(), "precision"), m.precision);
  EXPECT_EQ(h5::read_string_attribute(file(), "scene"), m.scene_name);
  EXPECT_EQ(h5::read_string_attribute(file(), "config_path"), m.config_path);
  EXPECT_EQ(h5::read_string_attribute(file(), "config"), m.config_json);
  EXPECT_EQ(h5::read_string_attribute(file(), "config_file"), m.config_file);
  EXPECT_EQ(h5::read_string_attribute(file(), "command_line"), m.command_line);
  EXPECT_EQ(read_integer_attribute(file(), "seed"), m.seed);
  EXPECT_EQ(h5::read_string_attribute(file(), "status"), "completed");
  EXPECT_EQ(h5::read_string_attribute(file(), "warnings"), "dt exceeds the acoustic bound\n");
  // ISO 8601 UTC, e.g. 2024-05-01T12:00:00Z: 20 characters ending in Z.
  for (const char* name : {"start_time", "end_time"}) {
    const std::string time = h5::read_string_attribute(file(), name);
    EXPECT_EQ(time.size(), 20u) << name << " = " << time;
    EXPECT_EQ(time.back(), 'Z') << name << " = " << time;
  }
  EXPECT_LE(h5::read_string_attribute(file(), "start_time"), h5::read_string_attribute(file(), "end_time"));
}

TEST_F(RunLogRoundTrip, GroupAttributesOfEveryType) {
  const h5::Handle ball = open_object(file(), "/bodies/ball");
  EXPECT_EQ(h5::read_double_attribute(ball.id(), "mass"), 4.1887902047863905);
  EXPECT_EQ(read_integer_attribute(ball.id(), "particle_count"), 3);
  const h5::Handle timing = open_object(file(), "/timing");
  EXPECT_EQ(read_string_list_attribute(timing.id(), "phase_names"),
            (std::vector<std::string>{"neighbours", "density", "forces"}));
  EXPECT_TRUE(has_attribute(timing.id(), "no_names"));
  EXPECT_TRUE(read_string_list_attribute(timing.id(), "no_names").empty());
}

TEST_F(RunLogRoundTrip, ScalarSeriesKeepsEveryRowInOrder) {
  EXPECT_EQ(h5::dataset_shape(file(), "/time"), std::vector<hsize_t>{kScalarRows});
  const std::vector<double> values = read_doubles(file(), "/time");
  ASSERT_EQ(values.size(), kScalarRows);
  for (std::size_t i = 0; i < kScalarRows; ++i) {
    ASSERT_EQ(values[i], scalar_row(i)) << "row " << i;  // float64 stored as written: bit-exact
  }
}

TEST_F(RunLogRoundTrip, VectorSeriesKeepsEveryRowInOrder) {
  const std::string path = "/bodies/ball/centre_of_mass";
  EXPECT_EQ(h5::dataset_shape(file(), path), (std::vector<hsize_t>{kVectorRows, 3}));
  const std::vector<double> values = read_doubles(file(), path);
  ASSERT_EQ(values.size(), 3 * kVectorRows);
  for (std::size_t i = 0; i < kVectorRows; ++i) {
    const std::array<double, 3> row = vector_row(i);
    for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(values[3 * i + c], row[c]) << "row " << i << " column " << c;
  }
}

TEST_F(RunLogRoundTrip, SeriesAreChunkedExtensibleAndDescribed) {
  struct Expected {
    std::string path, units, description;
    std::vector<hsize_t> max;
  };
  for (const Expected& e : {Expected{"/time", "s", "simulated time", {H5S_UNLIMITED}},
                            Expected{"/bodies/ball/centre_of_mass", "m", "centre of mass", {H5S_UNLIMITED, 3}}}) {
    EXPECT_TRUE(is_chunked(file(), e.path)) << e.path;
    EXPECT_EQ(max_shape(file(), e.path), e.max) << e.path;
    const h5::Handle set = open_object(file(), e.path);
    EXPECT_EQ(h5::read_string_attribute(set.id(), "units"), e.units) << e.path;
    EXPECT_EQ(h5::read_string_attribute(set.id(), "description"), e.description) << e.path;
  }
  const h5::Handle com = open_object(file(), "/bodies/ball/centre_of_mass");
  EXPECT_EQ(read_string_list_attribute(com.id(), "columns"), (std::vector<std::string>{"x", "y", "z"}));
  const h5::Handle time = open_object(file(), "/time");
  EXPECT_FALSE(has_attribute(time.id(), "columns")) << "no column names were given";
}

TEST_F(RunLogRoundTrip, IntegerArray) {
  EXPECT_EQ(h5::dataset_shape(file(), "/particles/body"), std::vector<hsize_t>{kBodies.size()});
  EXPECT_EQ(read_ints(file(), "/particles/body"), kBodies);
  const h5::Handle set = open_object(file(), "/particles/body");
  EXPECT_EQ(h5::read_string_attribute(set.id(), "description"), "body index of each particle");
  EXPECT_EQ(h5::read_string_attribute(set.id(), "units"), "1");
}

TEST_F(RunLogRoundTrip, SnapshotFieldsShapesAndUnits) {
  const std::string group = "/snapshots/00000040";
  const h5::Handle g = open_object(file(), group);
  EXPECT_EQ(h5::read_double_attribute(g.id(), "time"), 0.02);
  EXPECT_EQ(read_integer_attribute(g.id(), "step"), 40);
  const SnapshotData snap = sample_snapshot();
  struct Field {
    std::string name, units;
    const std::vector<float>* values;
    std::vector<hsize_t> shape;
  };
  for (const Field& f : {Field{"position", "m", &snap.position, {kParticles, 3}},
                         Field{"velocity", "m/s", &snap.velocity, {kParticles, 3}},
                         Field{"density", "kg/m^3", &snap.density, {kParticles}},
                         Field{"pressure", "Pa", &snap.pressure, {kParticles}}}) {
    const std::string path = group + "/" + f.name;
    EXPECT_EQ(h5::dataset_shape(file(), path), f.shape) << path;
    EXPECT_EQ(read_floats(file(), path), *f.values) << path;
    const h5::Handle set = open_object(file(), path);
    EXPECT_EQ(h5::read_string_attribute(set.id(), "units"), f.units) << path;
    EXPECT_FALSE(h5::read_string_attribute(set.id(), "description").empty()) << path;
  }
}

TEST(RunLog, AppendRejectsARowOfTheWrongWidth) {
  const TempDir dir;
  RunLog log((dir / "width.h5").string(), sample_metadata());
  const std::size_t series = log.add_series("/bodies/a/centre_of_mass", 3, "m", "centre of mass");
  const double two[2] = {1.0, 2.0};
  EXPECT_THROW(log.append(series, two), std::invalid_argument);
}

TEST(RunLog, SnapshotRejectsFieldsOfDifferentLengths) {
  const TempDir dir;
  RunLog log((dir / "snapshot.h5").string(), sample_metadata());
  const std::vector<float> three(3, 0.0f), six(6, 0.0f), one(1, 0.0f);
  // Two particles by density and pressure, one by position and velocity.
  EXPECT_THROW(log.add_snapshot(0, 0.0, SnapshotFields{three, three, {six.data(), 2}, {six.data(), 2}}),
               std::invalid_argument);
  EXPECT_THROW(log.add_snapshot(0, 0.0, SnapshotFields{six, six, {one.data(), 1}, {one.data(), 1}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace mssph::test
