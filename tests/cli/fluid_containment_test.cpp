// Fluid stays in its tank. configs/sphere_drop_fluid.json with the sphere heavier than shipped
// (still lighter than the fluid) at 4 cm spacing: with boundary particles alone holding the fluid,
// particles squeezed between the sinking sphere and the tank passed between the wall's particles
// (at density 900 kg/m^3 two of them by t = 0.35 s on `cpu`) and fell forever. Each run goes
// through `mssph run`; in every snapshot each fluid particle must lie within the tank: above its
// floor and between its side walls, the box its own boundary particles span (read from the log,
// so the check does not depend on how the walls are sampled). The tank is open at the top, so a
// splash may rise above it. A particle that crosses a wall is below or beside that box within a
// few hundredths of a second, as it falls at g.
#include "backend_on_this_machine.hpp"
#include "cli_fixture.hpp"

#include <array>
#include <cstdio>
#include <limits>
#include <ostream>

namespace mssph::test {
namespace {

struct ContainmentCase {
  std::string backend;
  double sphere_density;  // [kg/m^3]
};

void PrintTo(const ContainmentCase& c, std::ostream* out) {
  *out << c.backend << ", sphere " << c.sphere_density << " kg/m^3";
}

std::string snapshot_path(long long step) {
  char name[64];
  std::snprintf(name, sizeof name, "/snapshots/%08lld/position", step);
  return name;
}

class FluidContainment : public Cli, public ::testing::WithParamInterface<ContainmentCase> {};

TEST_P(FluidContainment, NoFluidParticleLeavesTheTank) {
  const ContainmentCase& c = GetParam();
  if (!backend_runs_here(c.backend)) GTEST_SKIP() << "no " << c.backend << " backend on this machine";
  const std::string out = work("drop.h5");
  // 0.45 s: the escape seen without the wall condition happens near t = 0.3 s.
  const double duration = 0.45, dt = 0.00025, snapshot_interval = 0.05;
  const ProcessResult r = mssph({"run", MSSPH_SOURCE_DIR "/configs/sphere_drop_fluid.json", "--backend", c.backend,
                                 "--threads", "1", "--set", "simulation/particle_spacing=0.04", "--set",
                                 "bodies/sphere/density=" + std::to_string(c.sphere_density), "--set",
                                 "simulation/duration=" + std::to_string(duration), "--set",
                                 "output/snapshot_interval=" + std::to_string(snapshot_interval), "--out", out, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const h5::Handle file = open_read_only(out);
  const std::vector<std::string> names =
      read_string_list_attribute(open_object(file.id(), "/particles").id(), "body_names");
  const auto index_of = [&](const std::string& name) {
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const int fluid = index_of("block"), tank = index_of("tank");
  ASSERT_LT(fluid, static_cast<int>(names.size()));
  ASSERT_LT(tank, static_cast<int>(names.size()));
  const std::vector<int> body = read_ints(file.id(), "/particles/body");

  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  const std::vector<double> start = read_doubles(file.id(), snapshot_path(0));
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i] != tank) continue;
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], start[3 * i + a]);
      hi[a] = std::max(hi[a], start[3 * i + a]);
    }
  }
  const auto steps_per_snapshot = static_cast<long long>(std::llround(snapshot_interval / dt));
  const auto last = static_cast<long long>(std::llround(duration / dt));
  for (long long step = 0; step <= last; step += steps_per_snapshot) {
    const std::vector<double> x = read_doubles(file.id(), snapshot_path(step));
    int outside = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] != fluid) continue;
      bool in = true;
      for (std::size_t a = 0; a < 3; ++a) in = in && x[3 * i + a] > lo[a] && (a == 2 || x[3 * i + a] < hi[a]);
      if (!in && outside++ == 0) {
        ADD_FAILURE() << "fluid particle " << i << " at (" << x[3 * i] << ", " << x[3 * i + 1] << ", " << x[3 * i + 2]
                      << ") m is outside the tank at step " << step;
      }
    }
    EXPECT_EQ(outside, 0) << "fluid particles outside the tank at step " << step;
  }
}

// The shipped sphere (500 kg/m^3) and two heavier ones; 900 and 950 kg/m^3 lost fluid before.
INSTANTIATE_TEST_SUITE_P(SphereDensities, FluidContainment,
                         ::testing::Values(ContainmentCase{"cpu", 500.0}, ContainmentCase{"cpu", 900.0},
                                           ContainmentCase{"cpu", 950.0}, ContainmentCase{"reference", 900.0},
                                           ContainmentCase{"cuda", 900.0}, ContainmentCase{"cuda", 950.0}),
                         [](const ::testing::TestParamInfo<ContainmentCase>& param_info) {
                           return param_info.param.backend + "_" +
                                  std::to_string(static_cast<int>(param_info.param.sphere_density));
                         });

}  // namespace
}  // namespace mssph::test
