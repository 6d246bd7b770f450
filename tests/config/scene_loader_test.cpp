// load_scene and parse_scene: the shipped scenes, what each key becomes (values, units,
// defaults), `--set` overrides, and failures of the file itself (missing, not JSON).
#include "config/scene_loader.hpp"

#include "config_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace mssph {
namespace {

using nlohmann::json;
using test::input_error_of;
using test::read_json_file;
using testing::HasSubstr;
using testing::StartsWith;

const std::string kBase = std::string(MSSPH_SOURCE_DIR) + "/tests/config/data/base_scene.json";

std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(MSSPH_SOURCE_DIR) + "/configs")) {
    const std::string name = entry.path().filename().string();
    // Not scenes: the schemas and the sweep files (sweep_*.json, checked by tests/sweep).
    if (entry.path().extension() == ".json" && name.find(".schema.") == std::string::npos &&
        name.rfind("sweep_", 0) != 0) {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

// The smallest valid scene, for checking defaults.
json minimal_scene() {
  return json::parse(R"({
    "name": "minimal",
    "simulation": {"dt": 0.001, "duration": 0.1, "particle_spacing": 0.02},
    "bodies": {"drop": {"kind": "fluid", "shape": {"type": "sphere", "radius": 0.05},
                        "rest_density": 1000.0, "pressure_stiffness": 100.0}}
  })");
}

TEST(SceneLoader, ShippedScenesLoad) {
  const std::vector<std::filesystem::path> scenes = shipped_scenes();
  ASSERT_FALSE(scenes.empty());
  for (const auto& path : scenes) {
    SCOPED_TRACE(path.string());
    const Scene scene = load_scene(path.string());
    // Output files are named after the scene; the shipped ones match their file names.
    EXPECT_EQ(scene.name, path.stem().string());
    EXPECT_FALSE(scene.bodies.empty());
    EXPECT_EQ(scene.source_file, path.string());
  }
}

TEST(SceneLoader, ReadsEveryKeyOfTheBaseScene) {
  const Scene scene = load_scene(kBase);
  EXPECT_EQ(scene.name, "contract_base");
  const SimulationConfig& sim = scene.simulation;
  EXPECT_EQ(sim.dt, 0.0005);
  EXPECT_EQ(sim.duration, 0.01);
  EXPECT_EQ(sim.gravity, Eigen::Vector3d(0.0, 0.0, -9.81));
  EXPECT_EQ(sim.particle_spacing, 0.02);
  EXPECT_EQ(sim.smoothing_length, 0.04);
  EXPECT_EQ(sim.seed, 7u);
  EXPECT_EQ(sim.jitter, 0.1);
  EXPECT_EQ(sim.max_speed, 20.0);

  const BodyConfig* tank = scene.find_body("tank");
  ASSERT_NE(tank, nullptr);
  EXPECT_EQ(tank->kind, BodyKind::boundary);
  EXPECT_EQ(tank->shape.type, ShapeType::container);
  EXPECT_EQ(tank->shape.size, Eigen::Vector3d(0.4, 0.4, 0.4));
  EXPECT_EQ(tank->shape.wall_layers, 2);
  EXPECT_TRUE(tank->shape.open_top);

  // Inline keys override the material's: viscosity 2 over water's 1; the rest comes from water.
  const BodyConfig* pool = scene.find_body("pool");
  ASSERT_NE(pool, nullptr);
  EXPECT_EQ(pool->material.viscosity, 2.0);
  EXPECT_EQ(pool->material.rest_density, 1000.0);
  EXPECT_EQ(pool->material.pressure_stiffness, 100.0);
  EXPECT_EQ(pool->shape.size, Eigen::Vector3d(0.4, 0.4, 0.1));

  const BodyConfig* jelly = scene.find_body("jelly");
  ASSERT_NE(jelly, nullptr);
  EXPECT_EQ(jelly->kind, BodyKind::deformable);
  EXPECT_EQ(jelly->material.young_modulus, 2.0e4);
  EXPECT_EQ(jelly->material.poisson_ratio, 0.3);
  EXPECT_EQ(jelly->material.model, ElasticModel::corotated_linear);
  EXPECT_EQ(jelly->material.damping, 1.0);
  EXPECT_EQ(jelly->material.zero_energy_stiffness, 0.1);
  EXPECT_TRUE(jelly->material.kernel_gradient_correction);
  ASSERT_EQ(jelly->fixed_regions.size(), 1u);
  EXPECT_EQ(jelly->fixed_regions[0].min, Eigen::Vector3d(0.05, 0.05, 0.14));
  EXPECT_EQ(jelly->fixed_regions[0].max, Eigen::Vector3d(0.15, 0.15, 0.17));

  // Orientation is stored [qx, qy, qz, qw]: here a quarter turn about z.
  const BodyConfig* tool = scene.find_body("tool");
  ASSERT_NE(tool, nullptr);
  EXPECT_EQ(tool->kind, BodyKind::rigid);
  EXPECT_EQ(tool->density, 700.0);
  EXPECT_FALSE(tool->fixed);
  EXPECT_EQ(tool->velocity, Eigen::Vector3d(0.0, 0.0, -0.1));
  EXPECT_EQ(tool->angular_velocity, Eigen::Vector3d(0.0, 0.0, 1.0));
  const Eigen::Vector3d x_turned = tool->orientation * Eigen::Vector3d::UnitX();
  // The quaternion's components are rounded to 16 digits: 1e-15 covers that and the rotation.
  EXPECT_NEAR((x_turned - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-15);

  const BodyConfig* anvil = scene.find_body("anvil");
  ASSERT_NE(anvil, nullptr);
  EXPECT_TRUE(anvil->fixed);
  EXPECT_EQ(anvil->density, 7800.0);

  ASSERT_TRUE(scene.proxy.has_value());
  EXPECT_EQ(scene.proxy->body, "tool");
  EXPECT_EQ(scene.output.log_interval, 0.001);
  EXPECT_EQ(scene.output.snapshot_interval, 0.005);
  EXPECT_EQ(scene.output.flush_interval, 1.0);
}

// viscous_modulus is read in Pa s, and only with kernel-gradient correction: without it a rigid
// rotation has a strain rate, and the viscous stress would slow a spinning body.
TEST(SceneLoader, ViscousModulusNeedsKernelGradientCorrection) {
  const Scene scene = load_scene(kBase, {"bodies/jelly/viscous_modulus=12.5"});
  EXPECT_EQ(scene.find_body("jelly")->material.viscous_modulus, 12.5);
  EXPECT_EQ(load_scene(kBase).find_body("jelly")->material.viscous_modulus, 0.0);
  const std::string message = input_error_of([&] {
    load_scene(kBase, {"bodies/jelly/viscous_modulus=12.5", "bodies/jelly/kernel_gradient_correction=false"});
  });
  EXPECT_THAT(message, HasSubstr("/bodies/jelly/kernel_gradient_correction"));
  EXPECT_THAT(message, HasSubstr("expected true where viscous_modulus > 0"));
  EXPECT_THAT(input_error_of([&] { load_scene(kBase, {"bodies/pool/viscous_modulus=1"}); }),
              HasSubstr("applies to deformable bodies only"));
}

// viscosity_model chooses the viscous force for the whole scene (by default paper:
// DefaultsOfOptionalKeys); a misspelt model is named with its path and the models there are.
TEST(SceneLoader, ViscosityModelIsOneOfTheNamedModels) {
  EXPECT_EQ(load_scene(kBase, {"simulation/viscosity_model=full_stress"}).simulation.viscosity_model,
            ViscosityModel::full_stress);
  const std::string message = input_error_of([&] { load_scene(kBase, {"simulation/viscosity_model=stress"}); });
  EXPECT_THAT(message, HasSubstr("/simulation/viscosity_model"));
  EXPECT_THAT(message, HasSubstr("full_stress"));
}

// neighbour_lists: by size (the default, DefaultsOfOptionalKeys) unless a scene asks for lists
// always; another value is refused in data/scene_cases.json (neighbour_lists_never).
TEST(SceneLoader, NeighbourListsMayBeAskedForAlways) {
  EXPECT_EQ(load_scene(kBase, {"simulation/neighbour_lists=always"}).simulation.neighbour_lists,
            NeighbourListUse::always);
}

TEST(SceneLoader, BodiesComeInNameOrder) {
  // nlohmann::json keeps object members sorted by key, so body indices (particle order, the
  // run log's body index) follow the names, not the order in the file.
  const Scene scene = load_scene(kBase);
  std::vector<std::string> names;
  for (const BodyConfig& b : scene.bodies) names.push_back(b.name);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(names.size(), 5u);
}

TEST(SceneLoader, DefaultsOfOptionalKeys) {
  const Scene scene = parse_scene(minimal_scene(), "minimal.json");
  const SimulationConfig& sim = scene.simulation;
  EXPECT_EQ(sim.gravity, Eigen::Vector3d(0.0, 0.0, -9.81));
  EXPECT_EQ(sim.smoothing_length, 2.0 * sim.particle_spacing);
  EXPECT_EQ(sim.seed, 0u);
  EXPECT_EQ(sim.jitter, 0.0);
  EXPECT_EQ(sim.max_speed, 50.0);
  EXPECT_FALSE(sim.domain.has_value());
  EXPECT_EQ(sim.max_lost_mass_fraction, 0.001);
  EXPECT_EQ(sim.viscosity_model, ViscosityModel::paper);
  EXPECT_FALSE(sim.sample_rigid_interiors);
  EXPECT_EQ(sim.neighbour_lists, NeighbourListUse::automatic);
  const BodyConfig& drop = scene.bodies.at(0);
  EXPECT_EQ(drop.position, Eigen::Vector3d::Zero());
  EXPECT_EQ(drop.velocity, Eigen::Vector3d::Zero());
  EXPECT_TRUE(drop.orientation.isApprox(Eigen::Quaterniond::Identity()));
  EXPECT_EQ(drop.material.viscosity, 0.0);
  EXPECT_EQ(drop.material.model, ElasticModel::saint_venant_kirchhoff);
  EXPECT_TRUE(drop.material.kernel_gradient_correction);
  EXPECT_EQ(drop.material.viscous_modulus, 0.0);
  EXPECT_FALSE(scene.proxy.has_value());
  EXPECT_EQ(scene.output.log_interval, 0.0);
  EXPECT_EQ(scene.output.snapshot_interval, 0.0);
  EXPECT_EQ(scene.output.flush_interval, 2.0);
  EXPECT_EQ(scene.description, "");
}

TEST(SceneLoader, ContainerWallsDefaultToOneKernelSupport) {
  // ceil(h / dx) layers: a particle touching the inner wall sees wall across its whole support.
  for (const double ratio : {1.0, 2.0, 2.5, 3.0, 4.0}) {
    json doc = minimal_scene();
    doc["simulation"]["smoothing_length"] = ratio * 0.02;
    doc["bodies"]["walls"] = {{"kind", "boundary"},
                              {"shape", {{"type", "container"}, {"inner_size", {0.2, 0.2, 0.2}}}},
                              {"rest_density", 1000.0},
                              {"pressure_stiffness", 100.0}};
    const Scene scene = parse_scene(doc, "walls.json");
    const BodyConfig* walls = scene.find_body("walls");
    ASSERT_NE(walls, nullptr);
    EXPECT_EQ(walls->shape.wall_layers, static_cast<int>(std::ceil(ratio))) << "h / dx = " << ratio;
    EXPECT_TRUE(walls->shape.open_top);
  }
}

TEST(SceneLoader, TheDocumentIsRecordedAfterOverrides) {
  const Scene scene = load_scene(kBase, {"simulation/dt=0.00025"});
  EXPECT_EQ(scene.document["simulation"]["dt"], 0.00025);
  EXPECT_EQ(scene.document["name"], "contract_base");
}

TEST(SetOverride, ParsesJsonValuesAndTakesOtherTextAsAString) {
  const Scene scene = load_scene(
      kBase, {"simulation/dt=0.00025", "/simulation/gravity=[0, 0, -1.62]", "bodies/jelly/strain=green_saint_venant",
              "bodies/anvil/fixed=false", "description=\"quoted text\"", "simulation/seed=11"});
  EXPECT_EQ(scene.simulation.dt, 0.00025);
  EXPECT_EQ(scene.simulation.gravity, Eigen::Vector3d(0.0, 0.0, -1.62));
  EXPECT_EQ(scene.find_body("jelly")->material.model, ElasticModel::saint_venant_kirchhoff);
  EXPECT_FALSE(scene.find_body("anvil")->fixed);
  EXPECT_EQ(scene.description, "quoted text");
  EXPECT_EQ(scene.simulation.seed, 11u);
}

TEST(SetOverride, LaterOverridesWin) {
  const Scene scene = load_scene(kBase, {"simulation/jitter=0.2", "simulation/jitter=0.05"});
  EXPECT_EQ(scene.simulation.jitter, 0.05);
}

TEST(SetOverride, MayAddAKeyWhichIsThenValidatedLikeTheFile) {
  ASSERT_FALSE(read_json_file(kBase)["bodies"]["anvil"].contains("velocity"));
  const Scene scene = load_scene(kBase, {"bodies/anvil/velocity=[1, 0, 0]"});
  EXPECT_EQ(scene.find_body("anvil")->velocity, Eigen::Vector3d(1.0, 0.0, 0.0));
  EXPECT_EQ(input_error_of([&] { load_scene(kBase, {"simulation/time_step=0.001"}); }),
            kBase +
                ": /simulation/time_step: unknown key 'time_step'; allowed keys: dt duration gravity "
                "particle_spacing smoothing_length seed jitter max_speed domain max_lost_mass_fraction viscosity_model "
                "sample_rigid_interiors neighbour_lists (this value comes from --set simulation/time_step=0.001)");
  EXPECT_EQ(input_error_of([&] { load_scene(kBase, {"simulation/dt=fast"}); }),
            kBase +
                ": /simulation/dt: expected a number > 0, got string \"fast\" (this value comes from --set "
                "simulation/dt=fast)");
}

// Strict JSON: a key twice in one object, or a number beyond a double, is an error with its path.
TEST(StrictJson, DuplicateKeysAndOverflowingNumbersAreRejectedWithTheirPath) {
  EXPECT_EQ(input_error_of([&] {
              parse_scene_text(R"({"name": "a", "bodies": {"b": {"kind": "fluid", "kind": "rigid"}}})", "s.json");
            }),
            "s.json: /bodies/b/kind: duplicate key 'kind' (JSON leaves its meaning undefined; keep one)");
  EXPECT_EQ(input_error_of([&] { parse_scene_text(R"({"name": "a", "list": [1, {"x": 2, "x": 3}]})", "s.json"); }),
            "s.json: /list/1/x: duplicate key 'x' (JSON leaves its meaning undefined; keep one)");
  const std::string overflow =
      input_error_of([&] { parse_scene_text(R"({"simulation": {"g": [0, 1e400]}})", "s.json"); });
  EXPECT_EQ(overflow.rfind("s.json: /simulation/g/1: ", 0), 0u) << overflow;
  // The same key in two objects is no duplicate.
  const std::string other = input_error_of([&] { parse_scene_text(R"({"a": {"k": 1}, "b": {"k": 2}})", "s.json"); });
  EXPECT_EQ(other.find("duplicate"), std::string::npos) << other;
}

TEST(SetOverride, RejectsAnAssignmentWithoutPathOrEquals) {
  EXPECT_EQ(input_error_of([&] { load_scene(kBase, {"simulation/dt"}); }),
            kBase + ": --set simulation/dt: expected PATH=VALUE, e.g. bodies/block/young_modulus=5e4");
  EXPECT_THAT(input_error_of([&] { load_scene(kBase, {"=0.001"}); }),
              StartsWith(kBase + ": --set =0.001: expected PATH=VALUE"));
}

TEST(SetOverride, RejectsAPathWhoseParentIsNotAnObjectOfTheScene) {
  EXPECT_EQ(input_error_of([&] { load_scene(kBase, {"bodies/ghost/density=1"}); }),
            kBase + ": --set bodies/ghost/density=1: /bodies/ghost is not an object in the scene");
  EXPECT_EQ(input_error_of([&] { load_scene(kBase, {"simulation/dt/value=1"}); }),
            kBase + ": --set simulation/dt/value=1: /simulation/dt is not an object in the scene");
  EXPECT_EQ(
      input_error_of([&] { load_scene(kBase, {"bodies/jelly/fixed_regions/0=1"}); }),
      kBase + ": --set bodies/jelly/fixed_regions/0=1: /bodies/jelly/fixed_regions is not an object in the scene");
}

TEST(SetOverride, RejectsAMalformedPointer) {
  // '~' must be followed by 0 or 1 in a JSON pointer.
  EXPECT_THAT(input_error_of([&] { load_scene(kBase, {"bodies/a~2b/kind=fluid"}); }),
              StartsWith(kBase + ": --set bodies/a~2b/kind=fluid: invalid path:"));
}

TEST(SceneFile, MissingFileIsNamed) {
  const std::string path = std::string(MSSPH_SOURCE_DIR) + "/configs/no_such_scene.json";
  EXPECT_EQ(input_error_of([&] { load_scene(path); }), path + ": cannot open scene file");
}

TEST(SceneFile, InvalidJsonNamesTheLineAndColumn) {
  // The stray '@' is the first character that is not JSON; editors count lines and columns from 1.
  const std::string text = "{\n  \"name\": \"broken\",\n  \"simulation\": {\"dt\": @}\n}\n";
  const test::TempFile file("broken.json", text);
  const std::string& path = file.path();
  const std::size_t at = text.find('@');
  const std::size_t line_start = text.rfind('\n', at) + 1;
  const std::size_t line =
      static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 1;
  const std::size_t column = at - line_start + 1;
  const std::string message = input_error_of([&] { load_scene(path); });
  EXPECT_THAT(message,
              StartsWith(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": invalid JSON: "));
  EXPECT_EQ(line, 3u);  // the fixture's own layout, so the check above is not vacuous
}

TEST(SceneFile, TruncatedJsonIsInvalid) {
  const test::TempFile file("truncated.json", "{\"name\": \"cut\", \"simulation\": {");
  const std::string& path = file.path();
  EXPECT_THAT(input_error_of([&] { load_scene(path); }), HasSubstr(": invalid JSON: "));
  EXPECT_THAT(input_error_of([&] { load_scene(path); }), StartsWith(path + ":1:"));
}

}  // namespace
}  // namespace mssph
