// The start-up time-step checks: each bound warns just above its limit and stays quiet just
// below it. The limits are worked out by hand below from the bounds' formulas (docs/model.md:
// acoustic 0.25 h / (c + v), viscous 0.125 h^2 rho0 / mu, body force 0.25 sqrt(h / |g|), elastic
// 0.25 h / c_p, viscoelastic 0.05 h^2 rho0 / ((eta / E) (lambda + 2 mu))), for h = 2 dx = 0.04 m.
#include "run/stability.hpp"

#include "config/scene_loader.hpp"
#include "model/scene_builder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace mssph {
namespace {

using nlohmann::json;
using testing::AllOf;
using testing::Contains;
using testing::HasSubstr;
using testing::IsEmpty;
using testing::Not;

// One 10 cm cube of `material` at rest (or moving at `speed` along x), no gravity unless given.
std::vector<std::string> warnings_for(double dt, const json& material, const std::string& kind = "fluid",
                                      double speed = 0.0, double gravity = 0.0) {
  json block = {{"kind", kind}, {"shape", {{"type", "box"}, {"size", {0.1, 0.1, 0.1}}}}};
  if (kind != "boundary") block["velocity"] = {speed, 0.0, 0.0};
  block.update(material);
  const json doc = {
      {"name", "stability"},
      {"simulation", {{"dt", dt}, {"duration", 1.0}, {"particle_spacing", 0.02}, {"gravity", {0.0, 0.0, -gravity}}}},
      {"bodies", {{"block", block}}}};
  return stability_warnings(build_particles(parse_scene(doc, "stability.json")));
}

// k = 100 m^2/s^2 (c = 10 m/s), inviscid: acoustic limit 0.25 * 0.04 / 10 = 1.0e-3 s.
const json kWater = {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}};

TEST(StabilityWarnings, AcousticBoundOfTheSoundSpeed) {
  EXPECT_THAT(warnings_for(0.95e-3, kWater), IsEmpty());
  EXPECT_THAT(warnings_for(1.05e-3, kWater), Contains(AllOf(HasSubstr("\"block\""), HasSubstr("acoustic"))));
}

TEST(StabilityWarnings, AcousticBoundIncludesTheFastestParticle) {
  // At 10 m/s the limit halves: 0.25 * 0.04 / (10 + 10) = 0.5e-3 s.
  EXPECT_THAT(warnings_for(0.45e-3, kWater, "fluid", 10.0), IsEmpty());
  EXPECT_THAT(warnings_for(0.55e-3, kWater, "fluid", 10.0), Contains(HasSubstr("acoustic")));
}

TEST(StabilityWarnings, ViscousBound) {
  // mu = 10 Pa s: 0.125 * 0.04^2 * 1000 / 10 = 0.02 s; k = 1e-4 (c = 0.01 m/s) puts the acoustic
  // limit at 1 s, out of the way.
  const json syrup = {{"rest_density", 1000.0}, {"pressure_stiffness", 1e-4}, {"viscosity", 10.0}};
  EXPECT_THAT(warnings_for(0.019, syrup), IsEmpty());
  EXPECT_THAT(warnings_for(0.021, syrup), Contains(HasSubstr("viscous")));
}

TEST(StabilityWarnings, BodyForceBound) {
  // |g| = 9.81 m/s^2: 0.25 * sqrt(0.04 / 9.81) = 0.01596 s.
  const json slow = {{"rest_density", 1000.0}, {"pressure_stiffness", 1e-4}};
  EXPECT_THAT(warnings_for(0.0155, slow, "fluid", 0.0, 9.81), IsEmpty());
  EXPECT_THAT(warnings_for(0.0165, slow, "fluid", 0.0, 9.81), Contains(HasSubstr("body-force")));
}

TEST(StabilityWarnings, ElasticBoundOfThePressureWaveSpeed) {
  // E = 1e5 Pa, nu = 0.3: lambda + 2 mu = E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 134615 Pa,
  // c_p = sqrt(134615 / 1000) = 11.60 m/s, limit 0.25 * 0.04 / 11.60 = 8.62e-4 s.
  const json rubber = {
      {"rest_density", 1000.0}, {"pressure_stiffness", 1e-4}, {"young_modulus", 1e5}, {"poisson_ratio", 0.3}};
  EXPECT_THAT(warnings_for(8.4e-4, rubber, "deformable"), IsEmpty());
  EXPECT_THAT(warnings_for(8.8e-4, rubber, "deformable"), Contains(HasSubstr("elastic")));
}

TEST(StabilityWarnings, ViscoelasticBoundOfTheViscousModulus) {
  // E = 1e3 Pa (elastic limit 0.25 * 0.04 / 1.160 = 8.6e-3 s, out of the way), nu = 0.3,
  // eta = 10 Pa s: (eta / E) (lambda + 2 mu) = 0.01 * 1346.15 = 13.46 Pa s, limit
  // 0.05 * 0.04^2 * 1000 / 13.46 = 5.94e-3 s.
  const json gel = {{"rest_density", 1000.0}, {"pressure_stiffness", 1e-4}, {"young_modulus", 1e3},
                    {"poisson_ratio", 0.3},   {"viscous_modulus", 10.0},    {"kernel_gradient_correction", true}};
  EXPECT_THAT(warnings_for(5.8e-3, gel, "deformable"), IsEmpty());
  EXPECT_THAT(warnings_for(6.1e-3, gel, "deformable"), Contains(HasSubstr("viscoelastic")));
}

TEST(StabilityWarnings, NearlyIncompressibleElasticity) {
  json rubber = {
      {"rest_density", 1000.0}, {"pressure_stiffness", 1e-4}, {"young_modulus", 1e3}, {"poisson_ratio", 0.45}};
  EXPECT_THAT(warnings_for(1e-4, rubber, "deformable"), IsEmpty());
  rubber["poisson_ratio"] = 0.46;
  EXPECT_THAT(warnings_for(1e-4, rubber, "deformable"), Contains(HasSubstr("poisson_ratio = 0.46")));
}

TEST(StabilityWarnings, BoundariesNeverMoveAndAreNotChecked) {
  EXPECT_THAT(warnings_for(1.05e-3, kWater, "boundary"), Not(Contains(HasSubstr("acoustic"))));
}

}  // namespace
}  // namespace mssph
