// Checkpoints in a run log (io/checkpoint_io.hpp, RunLog::write_checkpoint and the restart
// constructor): every element type comes back bit for bit, the two slots alternate so that a
// checkpoint torn by a kill leaves the previous one readable, and a reopened log cuts its series
// back to their rows at the checkpoint and appends from there.
#include "h5_read.hpp"
#include "io/run_log.hpp"
#include "run_log_samples.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace mssph::test {
namespace {

StateArrays sample_state(double seed) {
  StateArrays state;
  // Values that do not survive a conversion through another type: a float32 with all its
  // mantissa bits, doubles below float32's range, a NaN, integers beyond 2^53.
  state.put("backend/position", std::vector<float>{0.1f + static_cast<float>(seed), -1e-38f, 3.4e38f,
                                                   std::numeric_limits<float>::quiet_NaN()});
  state.put("backend/time", std::vector<double>{seed, 1e-300, std::nextafter(1.0, 2.0)});
  state.put("haptics/session/next_tick", std::vector<std::int64_t>{(std::int64_t{1} << 62) + 1, -5});
  state.put("lost_mass/flags", std::vector<std::uint8_t>{0, 1, 255});
  state.put("empty", std::vector<double>{});
  return state;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  // memcmp of an empty vector's data() (possibly null) would be undefined even for zero bytes.
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same_state(const StateArrays& expected, const StateArrays& actual) {
  ASSERT_EQ(actual.arrays().size(), expected.arrays().size());
  for (const auto& [name, values] : expected.arrays()) {
    std::visit(
        [&, n = name](const auto& v) {
          using T = typename std::decay_t<decltype(v)>::value_type;
          EXPECT_TRUE(same_bits(v, actual.get<T>(n))) << n;
        },
        values);
  }
}

class Checkpoints : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  TempDir dir_;
};

TEST_F(Checkpoints, EveryElementTypeComesBackBitForBit) {
  const std::string out = path("log.h5");
  {
    RunLog log(out, sample_metadata());
    log.write_checkpoint(7, 0.5, sample_state(1.0));
  }
  const h5::Handle file = open_read_only(out + ".partial");
  const std::optional<Checkpoint> read = read_latest_checkpoint(file.id());
  ASSERT_TRUE(read);
  EXPECT_EQ(read->step, 7);
  EXPECT_EQ(read->time, 0.5);
  expect_same_state(sample_state(1.0), read->state);
}

TEST_F(Checkpoints, ALogWithoutOneHasNone) {
  const std::string out = path("log.h5");
  { RunLog log(out, sample_metadata()); }
  EXPECT_FALSE(read_latest_checkpoint(open_read_only(out + ".partial").id()));
}

long long slot_step(const std::string& path, const char* slot) {
  const h5::Handle file = open_read_only(path);
  return static_cast<long long>(h5::read_double_attribute(open_object(file.id(), slot).id(), "step"));
}

TEST_F(Checkpoints, TheLatestWinsAndATornSlotLeavesThePreviousOne) {
  const std::string out = path("log.h5");
  const std::string partial = out + ".partial";
  {
    RunLog log(out, sample_metadata());
    log.write_checkpoint(10, 1.0, sample_state(1.0));
    log.write_checkpoint(20, 2.0, sample_state(2.0));
  }
  // Two slots, one checkpoint each.
  const bool b_is_older = slot_step(partial, "/checkpoint/b") == 10;
  const std::string older = b_is_older ? "/checkpoint/b" : "/checkpoint/a";
  const std::string newer = b_is_older ? "/checkpoint/a" : "/checkpoint/b";
  ASSERT_EQ(slot_step(partial, older.c_str()), 10);
  ASSERT_EQ(slot_step(partial, newer.c_str()), 20);
  // A kill while the next checkpoint was written into the older slot: marked -1, its arrays
  // half new.
  {
    h5::Handle access = h5::property_list(H5Pcreate(H5P_FILE_ACCESS), "access");
    h5::check(H5Pset_file_locking(access.id(), false, true), "no locking");
    const h5::Handle file = h5::file(H5Fopen(partial.c_str(), H5F_ACC_RDWR, access.id()), "open");
    h5::write_attribute(open_object(file.id(), older).id(), "step", -1LL);
    const std::vector<double> garbage{-7.0, -7.0, -7.0};
    const h5::Handle time = open_object(file.id(), older + "/state/backend/time");
    h5::check(H5Dwrite(time.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, garbage.data()), "tear");
  }
  const std::optional<Checkpoint> after_tear = read_latest_checkpoint(open_read_only(partial).id());
  ASSERT_TRUE(after_tear);
  EXPECT_EQ(after_tear->step, 20);
  expect_same_state(sample_state(2.0), after_tear->state);
  // The next checkpoint goes into the torn slot, never over the one a restart would need.
  {
    RunLog reopened(OutputClaim::resume(out), RunLog::Restart{"mssph run --restart test"});
    reopened.write_checkpoint(30, 3.0, sample_state(3.0));
  }
  EXPECT_EQ(slot_step(partial, older.c_str()), 30);
  EXPECT_EQ(slot_step(partial, newer.c_str()), 20);
  const std::optional<Checkpoint> latest = read_latest_checkpoint(open_read_only(partial).id());
  ASSERT_TRUE(latest);
  EXPECT_EQ(latest->step, 30);
  expect_same_state(sample_state(3.0), latest->state);
}

TEST_F(Checkpoints, AReopenedLogCutsItsSeriesBackToTheCheckpointAndAppends) {
  const std::string out = path("log.h5");
  {
    RunLog log(out, sample_metadata());
    const std::size_t series = log.add_series("/x", 1, "m", "a series");
    for (std::size_t i = 0; i < 5; ++i) log.append(series, std::span<const double>(std::vector<double>{scalar_row(i)}));
    log.write_checkpoint(5, 0.5, sample_state(1.0));
    // Rows after the checkpoint, flushed: a restart must not keep them.
    for (std::size_t i = 0; i < 3; ++i) log.append(series, std::span<const double>(std::vector<double>{-1.0}));
    log.flush();
  }
  {
    RunLog reopened(OutputClaim::resume(out), RunLog::Restart{"mssph run --restart test"});
    ASSERT_NE(reopened.restart_point(), nullptr);
    EXPECT_EQ(reopened.restart_point()->step, 5);
    const std::size_t series = reopened.add_series("/x", 1, "m", "a series");
    for (std::size_t i = 5; i < 8; ++i)
      reopened.append(series, std::span<const double>(std::vector<double>{scalar_row(i)}));
    reopened.finish_completed();
  }
  const h5::Handle file = open_read_only(out);
  std::vector<double> expected;
  for (std::size_t i = 0; i < 8; ++i) expected.push_back(scalar_row(i));
  EXPECT_EQ(read_doubles(file.id(), "/x"), expected);
  EXPECT_EQ(h5::read_string_attribute(file.id(), "status"), "completed");
}

TEST_F(Checkpoints, AReopenedLogRefusesASeriesTheCheckpointDoesNotKnow) {
  const std::string out = path("log.h5");
  {
    RunLog log(out, sample_metadata());
    log.write_checkpoint(1, 0.1, sample_state(1.0));
    log.add_series("/added_after", 1, "m", "a series born after the checkpoint");
    log.flush();
  }
  RunLog reopened(OutputClaim::resume(out), RunLog::Restart{"mssph run --restart test"});
  EXPECT_THROW(reopened.add_series("/added_after", 1, "m", "a series born after the checkpoint"), InputError);
}

TEST(StateArrays, GettingTheWrongTypeOrSizeNamesTheArray) {
  StateArrays state;
  state.put("backend/position", std::vector<float>{1.0f, 2.0f});
  try {
    state.get<double>("backend/position");
    FAIL() << "a float32 array read as float64";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("backend/position"), std::string::npos) << e.what();
  }
  EXPECT_THROW(state.get<float>("backend/position", 3), InputError);
  EXPECT_THROW(state.get<float>("backend/velocity"), InputError);
  EXPECT_EQ(state.part("backend").get<float>("position", 2).size(), 2u);
}

}  // namespace
}  // namespace mssph::test
