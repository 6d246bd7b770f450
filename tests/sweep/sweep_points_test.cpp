// Expansion of a sweep into points (product, zip, repetitions), their validation through the
// scene loader, and the stable hash that names each point's log.
#include "sweep/sweep_points.hpp"
#include "sweep_test_files.hpp"
#include "util/errors.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;
using Values = std::vector<std::pair<std::string, nlohmann::json>>;

const nlohmann::json kStiffness = {{"path", "materials/contact/pressure_stiffness"},
                                   {"name", "k"},
                                   {"log", {{"from", 100}, {"to", 10000}, {"count", 3}}}};

class SweepPointsTest : public ::testing::Test {
 protected:
  sweep::SweepFile load(const nlohmann::json& document) {
    return sweep::load_sweep_file(write_json(dir_, "sweep.json", document), test_metrics());
  }
  std::vector<sweep::SweepPoint> points_of(const nlohmann::json& document, const std::vector<std::string>& cli = {}) {
    const sweep::SweepFile s = load(document);
    std::vector<sweep::SweepPoint> points = sweep::expand_points(s, cli);
    sweep::validate_points(s, cli, points);
    return points;
  }
  TempDir dir_;
};

TEST_F(SweepPointsTest, ProductRunsEveryCombinationLastParameterFastest) {
  const auto points = points_of(tiny_sweep({kStiffness, kDensity}));
  ASSERT_EQ(points.size(), 6u);
  const std::vector<Values> expected{{{"k", 100.0}, {"density", 400}},   {{"k", 100.0}, {"density", 600}},
                                     {{"k", 1000.0}, {"density", 400}},  {{"k", 1000.0}, {"density", 600}},
                                     {{"k", 10000.0}, {"density", 400}}, {{"k", 10000.0}, {"density", 600}}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].index, i);
    EXPECT_EQ(points[i].parameters, expected[i]) << i;
    EXPECT_FALSE(points[i].seed);
  }
  EXPECT_EQ(points[3].overrides,
            (std::vector<std::string>{"materials/contact/pressure_stiffness=1000.0", "bodies/ball/density=600"}));
  EXPECT_EQ(points[3].describe(), "k=1000.0 density=600");
}

TEST_F(SweepPointsTest, ZipPairsTheIthValues) {
  const auto points = points_of(
      tiny_sweep({kStiffness, {{"path", "bodies/ball/density"}, {"values", {300, 400, 500}}}}, {{"combine", "zip"}}));
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].parameters, (Values{{"k", 100.0}, {"density", 300}}));
  EXPECT_EQ(points[1].parameters, (Values{{"k", 1000.0}, {"density", 400}}));
  EXPECT_EQ(points[2].parameters, (Values{{"k", 10000.0}, {"density", 500}}));
}

TEST_F(SweepPointsTest, RepetitionsRepeatEveryCombinationWithEachSeed) {
  const auto points =
      points_of(tiny_sweep(nlohmann::json::array({kDensity}), {{"repetitions", {{"seeds", {7, 9, 11}}}}}));
  ASSERT_EQ(points.size(), 6u);
  const std::vector<long long> seeds{7, 9, 11, 7, 9, 11};
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(points[i].seed);
    EXPECT_EQ(*points[i].seed, seeds[i]);
    EXPECT_EQ(points[i].overrides.back(), "simulation/seed=" + std::to_string(seeds[i]));
    EXPECT_EQ(points[i].parameters[0].second, i < 3 ? 400 : 600);
  }
  EXPECT_EQ(points[1].describe(), "density=400 seed=9");
}

TEST_F(SweepPointsTest, OverridesApplyInOrderFileThenCommandLineThenParameters) {
  const auto points =
      points_of(tiny_sweep(nlohmann::json::array({kDensity}), {{"set", {{"simulation/duration", 0.1}}}}),
                {"simulation/duration=0.05"});
  EXPECT_EQ(points[0].overrides, (std::vector<std::string>{"simulation/duration=0.1", "simulation/duration=0.05",
                                                           "bodies/ball/density=400"}));
}

TEST(PointHash, IsFnv1aOfTheCompactSceneJson) {
  // Published FNV-1a 64 test vectors (the FNV reference suite; also Go's hash/fnv golden values).
  EXPECT_EQ(sweep::fnv1a_64_hex(""), "cbf29ce484222325");
  EXPECT_EQ(sweep::fnv1a_64_hex("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(sweep::fnv1a_64_hex("abc"), "e71fa2190541574b");
  const nlohmann::json scene{{"b", 1}, {"a", {0.5, "x"}}};
  EXPECT_EQ(sweep::point_hash(scene), sweep::fnv1a_64_hex(R"({"a":[0.5,"x"],"b":1})")) << "compact, keys sorted";
}

TEST_F(SweepPointsTest, HashesAreStableAndFollowTheScene) {
  const auto first = points_of(tiny_sweep({kStiffness, kDensity}));
  const auto again = points_of(tiny_sweep({kDensity, kStiffness}));  // other parameter order, same scenes
  std::set<std::string> a, b;
  for (const auto& p : first) a.insert(p.hash);
  for (const auto& p : again) b.insert(p.hash);
  EXPECT_EQ(a.size(), first.size()) << "every point has its own name";
  EXPECT_EQ(a, b) << "a point's name depends on the scene it runs, not on how the sweep is written";
  // 1e3 and 1000.0 are the same value; a command-line --set elsewhere is a different scene.
  const auto written_otherwise =
      points_of(tiny_sweep({{{"path", "materials/contact/pressure_stiffness"}, {"values", {1e3}}}},
                           {{"set", {{"bodies/ball/density", 400}}}}));
  EXPECT_EQ(written_otherwise[0].hash, first[2].hash);
  const auto coarse = points_of(tiny_sweep({kStiffness, kDensity}), {"simulation/duration=0.01"});
  EXPECT_NE(coarse[0].hash, first[0].hash);
  EXPECT_EQ(first[0].log_name(), "point-" + first[0].hash + ".h5");
}

TEST_F(SweepPointsTest, APointTheSceneLoaderRejectsStopsTheSweepNamingIt) {
  const sweep::SweepFile s = load(tiny_sweep({{{"path", "simulation/dt"}, {"values", {0.0005, -1}}}}));
  auto points = sweep::expand_points(s, {});
  try {
    sweep::validate_points(s, {}, points);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("point 1 (dt=-1)"));
    EXPECT_THAT(e.what(), HasSubstr("tiny_drop.json: /simulation/dt: expected a number > 0"));
  }
}

TEST_F(SweepPointsTest, ACommandLineSetOfASweptPathIsRejected) {
  const sweep::SweepFile s = load(tiny_sweep(nlohmann::json::array({kDensity})));
  auto points = sweep::expand_points(s, {"bodies/ball/density=5"});
  EXPECT_THROW(sweep::validate_points(s, {"bodies/ball/density=5"}, points), InputError);
}

}  // namespace
}  // namespace mssph::test
