// Shards: --shard K/N and a Slurm array task's environment; N shards together run every point once.
#include "sweep/shard.hpp"
#include "util/errors.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

namespace mssph::test {
namespace {

using sweep::Shard;

TEST(Shard, TheUnionOfAllShardsIsEveryPointExactlyOnce) {
  for (std::size_t n = 1; n <= 7; ++n) {
    std::vector<int> runs(23, 0);
    for (std::size_t k = 0; k < n; ++k) {
      const Shard shard = sweep::parse_shard(std::to_string(k) + "/" + std::to_string(n));
      for (std::size_t i = 0; i < runs.size(); ++i) runs[i] += shard.contains(i) ? 1 : 0;
    }
    for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i], 1) << "point " << i << " with " << n << " shards";
  }
}

TEST(Shard, BadShardsAreRejected) {
  for (const char* text : {"", "1", "2/2", "-1/2", "0/0", "a/b", "1/2/3", " 0/2"}) {
    EXPECT_THROW(sweep::parse_shard(text), InputError) << text;
  }
}

TEST(Shard, SlurmArrayTaskIdAndCount) {
  const auto s = sweep::shard_from_slurm({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "5"}});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->describe(), "2/5");
}

TEST(Shard, SlurmArrayMinAndMaxWithoutCount) {
  // --array=10-13: tasks 10..13 are shards 0..3 of 4.
  const auto s = sweep::shard_from_slurm(
      {{"SLURM_ARRAY_TASK_ID", "12"}, {"SLURM_ARRAY_TASK_MIN", "10"}, {"SLURM_ARRAY_TASK_MAX", "13"}});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->describe(), "2/4");
}

TEST(Shard, OutsideAnArrayThereIsNoShard) { EXPECT_FALSE(sweep::shard_from_slurm({{"SLURM_JOB_ID", "4"}})); }

TEST(Shard, InconsistentSlurmVariablesAreRejectedNamingThem) {
  try {
    // --array=3,7 resubmitted by hand: 2 tasks whose ids do not count from the minimum.
    sweep::shard_from_slurm({{"SLURM_ARRAY_TASK_ID", "7"},
                             {"SLURM_ARRAY_TASK_COUNT", "2"},
                             {"SLURM_ARRAY_TASK_MIN", "3"},
                             {"SLURM_ARRAY_TASK_MAX", "7"}});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("SLURM_ARRAY_TASK_ID=7"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--shard K/N"));
  }
  EXPECT_THROW(sweep::shard_from_slurm({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}), InputError);
  EXPECT_THROW(sweep::shard_from_slurm({{"SLURM_ARRAY_TASK_ID", "0"}}), InputError);
}

}  // namespace
}  // namespace mssph::test
