// The simulation domain through `mssph run`: tests/data/fluid_fling.json throws a 32-particle
// block of fluid sideways at 4 m/s over a 50 cm slab. Its default domain reaches
// 0.5 * 0.5 m + h = 0.35 m beyond the slab's edge (x = 0.55 m), so the block, starting at
// x <= 0.075 m, crosses it after about (0.55 - 0.075) / 4 = 0.12 s: past the default 0.1 % of
// its mass the run fails with its own reason; with the whole mass allowed it completes and
// reports how many particles left.
#include "backend_on_this_machine.hpp"
#include "cli_fixture.hpp"

namespace mssph::test {
namespace {

const std::string kFlingScene = data_file("fluid_fling.json");

class SimulationDomain : public Cli, public ::testing::WithParamInterface<std::string> {};

TEST_P(SimulationDomain, FluidThrownOutFailsPastTheLostMassFraction) {
  if (!backend_runs_here(GetParam())) GTEST_SKIP() << "no " << GetParam() << " backend on this machine";
  const std::string out = work("fling.h5");
  const ProcessResult r = mssph({"run", kFlingScene, "--backend", GetParam(), "--threads", "1", "--out", out, "-q"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("particles of body \"splash\" left the domain"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("blow-up"), std::string::npos) << "a lost particle is not a blow-up:\n" << r.err;
  const std::string status = status_of(out + ".partial");
  EXPECT_EQ(status.rfind("failed: ", 0), 0u) << status;
  EXPECT_NE(status.find("left the domain"), std::string::npos) << status;
  // The first particles leave near t = 0.12 s (see above); one of 32 is already past 0.1 %.
  const std::vector<double> time = read_doubles(open_read_only(out + ".partial").id(), "/time");
  ASSERT_FALSE(time.empty());
  EXPECT_GT(time.back(), 0.08);
  EXPECT_LT(time.back(), 0.16);
}

TEST_P(SimulationDomain, LostParticlesAreCountedAndReported) {
  if (!backend_runs_here(GetParam())) GTEST_SKIP() << "no " << GetParam() << " backend on this machine";
  const std::string out = work("fling.h5");
  const ProcessResult r = mssph({"run", kFlingScene, "--backend", GetParam(), "--threads", "1", "--out", out, "-q",
                                 "--set", "simulation/max_lost_mass_fraction=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("left the domain: splash "), std::string::npos) << r.out;
  const h5::Handle file = open_read_only(out);
  const std::vector<double> left = read_doubles(file.id(), "/bodies/splash/left_domain_count");
  ASSERT_EQ(left.size(), read_doubles(file.id(), "/time").size());
  EXPECT_EQ(left.front(), 0.0);
  for (std::size_t k = 1; k < left.size(); ++k) EXPECT_GE(left[k], left[k - 1]) << "a deactivated particle stays so";
  EXPECT_GT(left.back(), 0.0);
  EXPECT_LE(left.back(), 32.0);
  EXPECT_EQ(read_integer_attribute(open_object(file.id(), "/bodies/splash").id(), "left_domain_count"),
            static_cast<long long>(left.back()));
  // The slab never moves and never leaves.
  EXPECT_FALSE(has_attribute(open_object(file.id(), "/bodies/ground").id(), "left_domain_count"));
}

INSTANTIATE_TEST_SUITE_P(Backends, SimulationDomain, ::testing::Values("cpu", "reference", "cuda"));

using SimulationDomainInput = Cli;

TEST_F(SimulationDomainInput, AnInvertedDomainIsRefusedWithFileAndPath) {
  const ProcessResult r =
      mssph({"run", kFlingScene, "--set", R"(simulation/domain={"min":[0,0,0],"max":[1,-1,1]})", "-q"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(kFlingScene + ": /simulation/domain/max: expected max > min"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("comes from --set"), std::string::npos) << r.err;
  EXPECT_TRUE(work_entries().empty()) << "nothing is written";
}

}  // namespace
}  // namespace mssph::test
