// Reading sweep files: every key's acceptance, and each rejection with the file, JSON path and
// what was expected.
#include "sweep/sweep_file.hpp"
#include "sweep_test_files.hpp"
#include "util/errors.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace mssph::test {
namespace {

using sweep::load_sweep_file;
using ::testing::AllOf;
using ::testing::HasSubstr;

class SweepFileTest : public ::testing::Test {
 protected:
  sweep::SweepFile load(const nlohmann::json& document) {
    return load_sweep_file(write_json(dir_, "sweep.json", document), test_metrics());
  }
  // The InputError's message, or a failure when the file is accepted.
  std::string rejection(const nlohmann::json& document) {
    try {
      load(document);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << document.dump(2);
    return "";
  }
  TempDir dir_;
};

TEST_F(SweepFileTest, ReadsEveryKey) {
  const sweep::SweepFile s =
      load(tiny_sweep({{{"path", "/materials/contact/pressure_stiffness"},
                        {"name", "k"},
                        {"log", {{"from", 100}, {"to", 10000}, {"count", 3}}}},
                       {{"path", "bodies/ball/density"}, {"linear", {{"from", 400}, {"to", 600}, {"count", 3}}}}},
                      {{"description", "d"},
                       {"set", {{"simulation/duration", 0.15}}},
                       {"combine", "zip"},
                       {"repetitions", {{"seeds", {3, 4.0}}}},
                       {"metrics", {"final_status", "time_to_peak"}},
                       {"$schema", "x"}}));
  EXPECT_EQ(s.name, "test_sweep");
  EXPECT_EQ(s.scene_path, tiny_scene());
  ASSERT_EQ(s.parameters.size(), 2u);
  EXPECT_EQ(s.parameters[0].name, "k");
  EXPECT_EQ(s.parameters[0].path, "materials/contact/pressure_stiffness") << "the leading '/' is dropped, as by --set";
  EXPECT_EQ(s.parameters[0].scale, sweep::ValueScale::log);
  EXPECT_EQ(s.parameters[0].values, (std::vector<nlohmann::json>{100.0, 1000.0, 10000.0}));
  EXPECT_EQ(s.parameters[1].name, "density") << "the default name is the path's last key";
  EXPECT_EQ(s.parameters[1].values, (std::vector<nlohmann::json>{400.0, 500.0, 600.0}));
  EXPECT_EQ(s.fixed_overrides, std::vector<std::string>{"simulation/duration=0.15"});
  EXPECT_EQ(s.combine, sweep::Combine::zip);
  EXPECT_EQ(s.seeds, (std::vector<long long>{3, 4}));
  EXPECT_EQ(s.metrics, (std::vector<std::string>{"final_status", "time_to_peak"}));
}

TEST_F(SweepFileTest, DefaultsAreProductNoRepetitionsAndEveryMetric) {
  const sweep::SweepFile s = load(tiny_sweep(nlohmann::json::array({kDensity})));
  EXPECT_EQ(s.combine, sweep::Combine::product);
  EXPECT_TRUE(s.seeds.empty());
  EXPECT_EQ(s.metrics, test_metrics());
}

TEST_F(SweepFileTest, SceneIsFoundFromTheSweepFilesFolder) {
  const std::string path = MSSPH_SOURCE_DIR "/tests/data/sweeps/tiny_product.json";
  const sweep::SweepFile s =
      load_sweep_file(path, {"peak_interaction_force", "time_to_peak", "peak_rendered_force", "final_status"});
  EXPECT_EQ(s.scene_path, MSSPH_SOURCE_DIR "/tests/data/tiny_drop.json");
}

TEST(RangeValues, LogRangesAreGeometricAndLinearOnesEven) {
  // 10^4 to 10^6 in 5 values: ratio sqrt(10) each, to 10 significant digits.
  EXPECT_EQ(sweep::range_values(sweep::ValueScale::log, 1e4, 1e6, 5),
            (std::vector<double>{1e4, 31622.77660, 1e5, 316227.7660, 1e6}));
  EXPECT_EQ(sweep::range_values(sweep::ValueScale::linear, 0.1, 0.4, 4), (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
  EXPECT_EQ(sweep::range_values(sweep::ValueScale::log, 2e6, 2e4, 3), (std::vector<double>{2e6, 2e5, 2e4}))
      << "a range may run downwards";
}

TEST_F(SweepFileTest, RejectionsNameTheFileThePathAndWhatWasExpected) {
  const std::string file = (dir_ / "sweep.json").string();
  struct Case {
    nlohmann::json document;
    std::string pointer;
    std::string expected;
  };
  const std::vector<Case> cases{
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"colour", 1}}), "/colour", "unknown key"},
      {tiny_sweep(nlohmann::json::array()), "/parameters", "expected at least one parameter"},
      {tiny_sweep({{{"path", "bodies/ball/density"}, {"values", nlohmann::json::array()}}}), "/parameters/0/values",
       "empty list"},
      {tiny_sweep({{{"path", "bodies/ball/density"}, {"values", {1, 1}}}}), "/parameters/0/values/1",
       "duplicate value"},
      {tiny_sweep({{{"path", "bodies/ball/density"}}}), "/parameters/0", "exactly one of"},
      {tiny_sweep(
           {{{"path", "bodies/ball/density"}, {"values", {1}}, {"log", {{"from", 1}, {"to", 2}, {"count", 2}}}}}),
       "/parameters/0", "exactly one of"},
      {tiny_sweep({{{"path", "a/b"}, {"log", {{"from", 0}, {"to", 2}, {"count", 2}}}}}), "/parameters/0/log/from",
       "> 0"},
      {tiny_sweep({{{"path", "a/b"}, {"linear", {{"from", 0}, {"to", 2}, {"count", 1}}}}}),
       "/parameters/0/linear/count", "in [2, 100000]"},
      {tiny_sweep({{{"path", "a/b"}, {"linear", {{"from", 0}, {"to", 2}}}}}), "/parameters/0/linear/count", "missing"},
      {tiny_sweep({kDensity, kDensity}), "/parameters/1", "a second parameter named \"density\""},
      {tiny_sweep({{{"path", "bodies/ball/state"}, {"name", "state"}, {"values", {1}}}}), "/parameters/0/name",
       "taken by a summary column"},
      {tiny_sweep({{{"path", "x/final_status"}, {"values", {1}}}}), "/parameters/0", "is a metric's"},
      {tiny_sweep({{{"path", "simulation/seed"}, {"values", {1, 2}}}}), "/parameters/0/path", "repetitions"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"metrics", {"peak_force"}}}), "/metrics/0",
       "unknown metric \"peak_force\""},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"metrics", nlohmann::json::array()}}), "/metrics",
       "at least one metric"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"repetitions", {{"seeds", {1, -1}}}}}), "/repetitions/seeds/1",
       "an integer >= 0"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"repetitions", {{"seeds", nlohmann::json::array()}}}}),
       "/repetitions/seeds", "empty list"},
      {tiny_sweep({kDensity, {{"path", "a/b"}, {"values", {1, 2, 3}}}}, {{"combine", "zip"}}), "/combine",
       "density has 2, b has 3"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"combine", "cross"}}), "/combine",
       "expected one of \"product\", \"zip\""},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"set", {{"bodies/ball/density", 1}}}}),
       "/set/bodies~1ball~1density", "is swept"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"scene", "nowhere.json"}}), "/scene", "no scene file"},
      {tiny_sweep(nlohmann::json::array({kDensity}), {{"name", "has space"}}), "/name", "letters, digits"},
  };
  for (const Case& c : cases) {
    EXPECT_THAT(rejection(c.document), AllOf(HasSubstr(file + ": " + c.pointer + ": "), HasSubstr(c.expected)))
        << c.document.dump();
  }
}

TEST_F(SweepFileTest, BadJsonNamesLineAndColumn) {
  const std::string path = (dir_ / "broken.json").string();
  std::ofstream(path) << "{\n  \"name\": \"x\",,\n}";
  try {
    load_sweep_file(path, test_metrics());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path + ":2:"));
  }
}

}  // namespace
}  // namespace mssph::test
