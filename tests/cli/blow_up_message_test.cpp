// A blow-up names the step, the body, the particle, its position and velocity and the CFL numbers
// (src/run/simulation_run.cpp). tests/data/tiny_drop.json with max_speed 1e-4 m/s: the ball's
// particles exceed it after the first steps of free fall.
#include "cli_fixture.hpp"

#include <cmath>
#include <regex>

namespace mssph::test {
namespace {

using BlowUpMessage = Cli;

TEST_F(BlowUpMessage, NamesStepBodyParticlePositionVelocityAndCflNumbers) {
  const std::string out = work("blow_up.h5");
  const ProcessResult r = mssph(
      {"run", data_file("tiny_drop.json"), "--out", out, "--threads", "1", "-q", "--set", "simulation/max_speed=1e-4"});
  ASSERT_EQ(r.exit_code, 3) << r.err;
  const std::regex pattern(
      R"(blow-up at step (\d+), t = [^ ]+ s: body "ball" has a particle at [^ ]+ m/s, beyond simulation/max_speed = 0.0001 m/s; )"
      R"(particle (\d+) at \(([^,]+), ([^,]+), ([^)]+)\) m, velocity \(([^,]+), ([^,]+), ([^)]+)\) m/s; )"
      R"(CFL numbers: acoustic dt \(c \+ \|v\|\) / h = ([^ ]+) \(stable below 0.25\), advective dt \|v\| / h = ([^;]+);)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, pattern)) << r.err;
  EXPECT_GT(std::stoll(m[1]), 0);
  // The ball's 27 particles come first (bodies in name order, as /particles body_names lists them).
  EXPECT_LT(std::stoll(m[2]), 27);
  const double vx = std::stod(m[6]), vy = std::stod(m[7]), vz = std::stod(m[8]);
  const double speed = std::sqrt(vx * vx + vy * vy + vz * vz);
  EXPECT_GT(speed, 1e-4);
  // The scene: dt = 0.0005 s, h = 2 dx = 0.1 m, c = sqrt(k) = sqrt(500) m/s (material "contact").
  const double dt = 0.0005, h = 0.1, c = std::sqrt(500.0);
  EXPECT_NEAR(std::stod(m[9]), dt * (c + speed) / h, 1e-5);
  EXPECT_NEAR(std::stod(m[10]), dt * speed / h, 1e-8);
}

}  // namespace
}  // namespace mssph::test
