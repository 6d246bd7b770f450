// The start-up check of bodies whose particles start closer than a spacing: a fluid in a
// container whose inner height is not a whole number of spacings is warned of, one that is is
// not, whatever the number of threads, and no shipped scene starts crowded.
#include "run/crowded_start.hpp"

#include "config/scene_loader.hpp"
#include "model/scene_builder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <omp.h>

namespace mssph {
namespace {

using nlohmann::json;
using testing::AllOf;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;

// A 10 cm cube of water standing on the floor of a tank 10 cm wide and `tank_height` high, at
// dx = 2 cm, lattice jitter `jitter`.
std::vector<std::string> warnings_for(double tank_height, double jitter = 0.0) {
  const json material = {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}};
  const json doc = {{"name", "crowded"},
                    {"simulation", {{"dt", 1e-4}, {"duration", 1.0}, {"particle_spacing", 0.02}, {"jitter", jitter}}},
                    {"materials", {{"water", material}}},
                    {"bodies",
                     {{"tank",
                       {{"kind", "boundary"},
                        {"material", "water"},
                        {"shape", {{"type", "container"}, {"inner_size", {0.1, 0.1, tank_height}}}},
                        {"position", {0.0, 0.0, 0.5 * tank_height}}}},
                      {"water",
                       {{"kind", "fluid"},
                        {"material", "water"},
                        {"shape", {{"type", "box"}, {"size", {0.1, 0.1, 0.1}}}},
                        {"position", {0.0, 0.0, 0.05}}}}}}};
  const Scene scene = parse_scene(doc, "crowded.json");
  return crowded_start_warnings(build_particles(scene), scene.simulation.jitter);
}

TEST(CrowdedStart, FluidInATankOfWholeSpacingsStartsOneSpacingFromItsWalls) {
  EXPECT_THAT(warnings_for(0.2), IsEmpty());
}

// An inner height of 10.25 spacings holds 10 whole cells, centred: the walls' lattice sits an
// eighth of a spacing above the fluid's, and the floor's top layer 0.875 spacings below the
// fluid's bottom layer.
TEST(CrowdedStart, TankOfAQuarterSpacingMoreCrowdsItsFluid) {
  EXPECT_THAT(warnings_for(0.205),
              ElementsAre(AllOf(HasSubstr("\"tank\" and \"water\""), HasSubstr("0.875 spacings"))));
}

// A wall and a fluid whose closest pairs tie exactly, half a spacing apart at ten places spread
// over the particle order: the warning names the first, whatever the number of threads that search.
TEST(CrowdedStart, ATieNamesThePairMetFirstWhateverTheThreadCount) {
  ParticleSetup setup;
  setup.spacing = 1.0;
  setup.bodies.resize(2);
  setup.bodies[0].name = "wall";
  setup.bodies[0].kind = BodyKind::boundary;
  setup.bodies[0].count = 10;
  setup.bodies[1].name = "water";
  setup.bodies[1].first = 10;
  setup.bodies[1].count = 10;
  for (const double y : {0.0, 0.5}) {
    for (int k = 0; k < 10; ++k) {
      setup.position.emplace_back(4.0 * (k + 1), y, 0.0);
      setup.body.push_back(y == 0.0 ? 0u : 1u);
    }
  }
  const int threads = omp_get_max_threads();
  std::vector<std::vector<std::string>> warnings;
  for (const int count : {1, 2, 3}) {
    omp_set_num_threads(count);
    warnings.push_back(crowded_start_warnings(setup, 0.0));
  }
  omp_set_num_threads(threads);
  EXPECT_THAT(warnings[0], ElementsAre(AllOf(HasSubstr("0.5 spacings"), HasSubstr("near [4, 0, 0]"))));
  EXPECT_EQ(warnings[1], warnings[0]);
  EXPECT_EQ(warnings[2], warnings[0]);
}

TEST(CrowdedStart, JitterOfAFifthOfASpacingLeavesNothingToCheck) { EXPECT_THAT(warnings_for(0.205, 0.2), IsEmpty()); }

TEST(CrowdedStart, NoShippedSceneStartsCrowded) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(MSSPH_SOURCE_DIR "/configs")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".json" && name.find("schema") == std::string::npos && name.rfind("sweep", 0) != 0)
      scenes.push_back(entry.path());
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(MSSPH_SOURCE_DIR "/validation")) {
    if (entry.path().filename() == "scene.json") scenes.push_back(entry.path());
  }
  ASSERT_GE(scenes.size(), 15u);
  for (const auto& path : scenes) {
    const Scene scene = load_scene(path.string());
    EXPECT_THAT(crowded_start_warnings(build_particles(scene), scene.simulation.jitter), IsEmpty()) << path;
  }
}

}  // namespace
}  // namespace mssph
