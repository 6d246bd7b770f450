// Device recordings on disk: both formats round-trip, and every malformed file is rejected with
// an InputError that names the file and the row of the problem.
#include "config/device_recording.hpp"
#include "temp_dir.hpp"
#include "util/errors.hpp"
#include "util/hdf5_handle.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <ostream>

namespace mssph::test {
namespace {

constexpr RecordingLimits kVirtuose{0.45};  // the 6D35-45's workspace radius [m]

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// An HDF5 file with /device/t and /device/pose as given (pose columns may be wrong on purpose).
void write_h5(const std::string& path, const std::vector<double>& t, const std::vector<double>& pose, hsize_t columns,
              bool with_pose = true) {
  h5::Handle file = h5::file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "create");
  h5::open_or_create_group(file.id(), "/device");
  const auto write = [&](const char* name, const std::vector<double>& values, std::vector<hsize_t> dims) {
    h5::Handle space = h5::dataspace(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), "space");
    h5::Handle set = h5::dataset(
        H5Dcreate2(file.id(), name, H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "create");
    h5::check(H5Dwrite(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write");
  };
  write("/device/t", t, {t.size()});
  if (with_pose) write("/device/pose", pose, {pose.size() / columns, columns});
}

const std::string kHeader = "t,x,y,z,qx,qy,qz,qw\n";
const std::string kGood = "0,0,0,0,0,0,0,1\n";

struct Malformed {
  const char* name;
  std::string content;  // CSV text
  const char* row;      // how the error names the row
  const char* problem;  // what it says is wrong
};

// Names the case in test listings (ctest shows parameters).
void PrintTo(const Malformed& m, std::ostream* out) { *out << m.name; }

class MalformedCsv : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedCsv, IsRejectedWithItsFileAndRowNamed) {
  TempDir dir;
  const std::string path = (dir / (std::string(GetParam().name) + ".csv")).string();
  write_text(path, GetParam().content);
  try {
    read_device_recording(path, kVirtuose);
    FAIL() << "accepted " << GetParam().name;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith(path + ": " + GetParam().row));
    EXPECT_THAT(e.what(), ::testing::HasSubstr(GetParam().problem));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, MalformedCsv,
    ::testing::Values(
        Malformed{"MissingColumn", "t,x,y,z,qx,qy,qz\n0,0,0,0,0,0,0\n", "line 1 (header)", "missing column \"qw\""},
        Malformed{"DuplicateColumn", "t,x,y,z,qx,qy,qz,qw,x\n", "line 1 (header)", "\"x\" appears twice"},
        Malformed{"ShortRow", kHeader + kGood + "0.001,0,0,0,0,0,1\n", "line 3", "expected 8 comma-separated values"},
        Malformed{"NotANumber", kHeader + "0,abc,0,0,0,0,0,1\n", "line 2", "column x: expected a number, got \"abc\""},
        Malformed{"EmptyField", kHeader + "0,0,,0,0,0,0,1\n", "line 2", "column y: expected a number"},
        Malformed{"NaN", kHeader + kGood + "0.001,0,0,0,0,nan,0,1\n", "line 3", "column qy: expected a finite number"},
        Malformed{"Infinite", kHeader + kGood + kGood + "0.002,inf,0,0,0,0,0,1\n", "line 4",
                  "column x: expected a finite"},
        Malformed{"DuplicateTime", kHeader + kGood + "0.001,0,0,0,0,0,0,1\n0.001,0,0,0,0,0,0,1\n", "line 4",
                  "duplicate time"},
        Malformed{"TimeGoesBack", kHeader + kGood + "0.002,0,0,0,0,0,0,1\n0.001,0,0,0,0,0,0,1\n", "line 4",
                  "out of order"},
        Malformed{"NonUnitQuaternion", kHeader + kGood + "0.001,0,0,0,0,0,0,0.9\n", "line 3", "has norm 0.9"},
        Malformed{"ZeroQuaternion", kHeader + "0,0,0,0,0,0,0,0\n", "line 2", "has norm 0"},
        Malformed{"OutsideWorkspace", kHeader + kGood + "0.001,0.3,0.3,0.2,0,0,0,1\n", "line 3",
                  "outside the workspace radius 0.45 m"},
        Malformed{"LineNumbersCountBlankLines", kHeader + kGood + "\n" + "0.001,0,0,0,0,0,0,2\n", "line 4",
                  "has norm 2"},
        Malformed{"EmptyFile", "", "empty file", "expected a header t,x,y,z,qx,qy,qz,qw"},
        Malformed{"HeaderOnly", kHeader, "the device recording holds no sample", "no sample"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(MalformedHdf5, EachProblemIsRejectedWithItsFileAndRowNamed) {
  TempDir dir;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> unit_rows = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  struct Case {
    const char* name;
    std::vector<double> t;
    std::vector<double> pose;
    hsize_t columns;
    bool with_pose;
    std::string expected;  // after "<path>: "
  };
  std::vector<double> with_nan = unit_rows;
  with_nan[2 * 7 + 5] = nan;  // row 2, qz
  std::vector<double> outside = unit_rows;
  outside[1 * 7 + 2] = -0.5;  // row 1, z
  std::vector<double> stretched = unit_rows;
  stretched[2 * 7 + 6] = 1.01;  // row 2, qw
  const std::vector<Case> cases = {
      {"no_pose", {0, 1, 2}, {}, 7, false, "missing dataset /device/pose"},
      {"six_columns", {0, 1, 2}, std::vector<double>(18, 0.0), 6, true, "/device/pose: expected shape [3, 7]"},
      {"nan", {0, 1, 2}, with_nan, 7, true, "/device row 2: column qz is not a finite number"},
      {"duplicate_time",
       {0, 1, 1},
       unit_rows,
       7,
       true,
       "/device row 2: t = 1 s is not after the previous sample's t = 1 s"},
      {"backwards_time", {0, 2, 1}, unit_rows, 7, true, "/device row 2: t = 1 s is not after"},
      {"outside", {0, 1, 2}, outside, 7, true, "/device row 1: position (0, 0, -0.5) m"},
      {"not_unit", {0, 1, 2}, stretched, 7, true, "/device row 2: quaternion (qx, qy, qz, qw) has norm 1.01"},
  };
  for (const Case& c : cases) {
    const std::string path = (dir / (std::string(c.name) + ".h5")).string();
    write_h5(path, c.t, c.pose, c.columns, c.with_pose);
    try {
      read_device_recording(path, kVirtuose);
      ADD_FAILURE() << "accepted " << c.name;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::StartsWith(path + ": " + c.expected)) << c.name;
    }
  }
}

TEST(DeviceRecordingFiles, UnknownFormatsAndMissingFilesAreInputErrors) {
  TempDir dir;
  write_text((dir / "poses.txt").string(), kHeader + kGood);
  EXPECT_THROW(read_device_recording((dir / "poses.txt").string(), kVirtuose), InputError);
  EXPECT_THROW(read_device_recording((dir / "absent.csv").string(), kVirtuose), InputError);
  write_text((dir / "garbage.h5").string(), "not hdf5");
  EXPECT_THROW(read_device_recording((dir / "garbage.h5").string(), kVirtuose), InputError);
  EXPECT_THROW(check_recording_path("out.json"), InputError);
  EXPECT_NO_THROW(check_recording_path("out.HDF5"));
}

TEST(DeviceRecordingFiles, BothFormatsRoundTripExactly) {
  TempDir dir;
  DeviceRecording recording;
  for (int i = 0; i < 50; ++i) {
    const double t = 1e-3 * i;
    recording.time.push_back(t);
    recording.pose.push_back(
        Pose{Eigen::Vector3d(0.1 * std::sin(7.0 * t), -0.3 * t, 1.0 / 3.0),
             Eigen::Quaterniond(Eigen::AngleAxisd(3.0 * t, Eigen::Vector3d(1, 2, 3).normalized()))});
  }
  for (const char* name : {"trajectory.csv", "trajectory.h5"}) {
    std::ofstream((dir / name).string(), std::ios::binary) << device_recording_bytes(name, recording);
    const DeviceRecording back = read_device_recording((dir / name).string(), kVirtuose);
    ASSERT_EQ(back.time, recording.time) << name;
    for (std::size_t i = 0; i < back.pose.size(); ++i) {
      ASSERT_EQ(back.pose[i].position, recording.pose[i].position) << name;
      // Reading normalises the quaternion: one rounding step of a unit norm.
      ASSERT_LT((back.pose[i].orientation.coeffs() - recording.pose[i].orientation.coeffs()).norm(), 1e-15) << name;
    }
  }
}

TEST(DeviceRecordingFiles, CsvColumnsMayComeInAnyOrderWithExtraColumns) {
  TempDir dir;
  write_text((dir / "reordered.csv").string(), "qw,buttons,x,y,z,qx,qy,qz,t\n1,0,0.1,0.2,0.3,0,0,0,0.5\n");
  const DeviceRecording r = read_device_recording((dir / "reordered.csv").string(), kVirtuose);
  ASSERT_EQ(r.time.size(), 1u);
  EXPECT_EQ(r.time[0], 0.5);
  EXPECT_EQ(r.pose[0].position, Eigen::Vector3d(0.1, 0.2, 0.3));
}

}  // namespace
}  // namespace mssph::test
