// The GPU's lanes per particle (kernels/common/team_lanes.hpp), on the resident threads of a
// 132-multiprocessor card (2048 each): teams while the scene fits, one lane beyond four waves at
// two lanes unless the scene asks for lists, and the bond passes' lanes within half the card.
#include "common/team_lanes.hpp"

#include <gtest/gtest.h>

#include <cstddef>

namespace mssph::kernels {
namespace {

constexpr std::size_t kResident = 132 * 2048;

TEST(TeamLanes, SmallScenesTakeTheMostLanesThatFitOneWave) {
  EXPECT_EQ(choose_team_lanes(kResident / 8, kResident, false), 8u);
  EXPECT_EQ(choose_team_lanes(kResident / 8 + 1, kResident, false), 4u);
  EXPECT_EQ(choose_team_lanes(kResident / 4, kResident, false), 4u);
  EXPECT_EQ(choose_team_lanes(kResident / 4 + 1, kResident, false), 2u);
  EXPECT_EQ(choose_team_lanes(2'000, kResident, false), 8u);
  EXPECT_EQ(choose_team_lanes(46'188, kResident, false), 4u);   // the 30k block
  EXPECT_EQ(choose_team_lanes(134'203, kResident, false), 2u);  // the 100k block
  EXPECT_EQ(choose_team_lanes(46'188, kResident, true), 4u) << "asking for lists never takes lanes away";
}

TEST(TeamLanes, TeamsOfTwoUpToFourWavesThenOneLaneUnlessListsAreAskedFor) {
  EXPECT_EQ(choose_team_lanes(2 * kResident, kResident, false), 2u);
  EXPECT_EQ(choose_team_lanes(2 * kResident + 1, kResident, false), 1u);
  EXPECT_EQ(choose_team_lanes(1'158'320, kResident, false), 1u);  // the 1M blocks
  EXPECT_EQ(choose_team_lanes(1'158'320, kResident, true), 2u);
  EXPECT_EQ(choose_team_lanes(2 * kResident + 1, kResident, true), 2u);
}

TEST(TeamLanes, BondTeamsFitOneWaveOfHalfTheResidentThreads) {
  EXPECT_EQ(choose_bond_team_lanes(16'000, kResident), 8u);
  EXPECT_EQ(choose_bond_team_lanes(kResident / 4, kResident), 2u);
  EXPECT_EQ(choose_bond_team_lanes(kResident, kResident), 1u);
}

}  // namespace
}  // namespace mssph::kernels
