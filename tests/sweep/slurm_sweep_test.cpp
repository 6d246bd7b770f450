// A sweep on a real Slurm cluster: the scripts of --emit-slurm are submitted to a single-node
// slurmctld + slurmd started by the test, the array tasks run the shards, the dependent merge
// job writes the summary, and that summary equals a local run's (the cpu backend gives
// bit-identical runs for the same scene and seed, so every metric must match exactly).
#include "slurm_cluster.hpp"
#include "sweep_cli_fixture.hpp"

#include <gmock/gmock.h>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

using SlurmSweep = SweepCli;

TEST_F(SlurmSweep, ArrayJobAndMergeGiveTheSummaryOfALocalRun) {
  SlurmCluster cluster;
  if (const auto why_not = cluster.start()) GTEST_SKIP() << "Slurm cannot be started here: " << *why_not;
  // The array tasks inherit this environment, OMP_NUM_THREADS=1 included (see SweepCli), so
  // they run the points with the same threads as the local run.

  const std::string slurm_out = work("slurm_sweep");
  const ProcessResult emitted =
      mssph({"sweep", tiny_product_sweep(), "--out", slurm_out, "--backend", "cpu", "--emit-slurm", "--shards", "2"});
  ASSERT_EQ(emitted.exit_code, 0) << emitted.err;
  const ProcessResult submitted = run_process({"/bin/bash", slurm_out + "/slurm/submit.sh"}, work_.path());
  ASSERT_EQ(submitted.exit_code, 0) << submitted.err << cluster.logs();
  EXPECT_THAT(submitted.out, HasSubstr("(2 tasks), merge job"));
  ASSERT_TRUE(cluster.wait_until_idle(300s)) << "jobs still queued after 300 s:\n"
                                             << cluster.client({"squeue"}).out << cluster.logs();

  // Each task ran its shard, and the merge ran after both.
  for (const char* shard : {"shard-0.out", "shard-1.out"}) {
    EXPECT_THAT(read_file(slurm_out + "/slurm/logs/" + shard), HasSubstr("(shard ")) << shard;
  }
  EXPECT_THAT(read_file(slurm_out + "/slurm/logs/merge.out"), HasSubstr("4 points, 4 completed"));

  const ProcessResult local = mssph({"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cpu"});
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const std::string from_slurm = read_file(slurm_out + "/summary.csv");
  EXPECT_EQ(from_slurm, read_file(out() + "/summary.csv")) << "Slurm and local summaries differ";
  EXPECT_THAT(from_slurm, HasSubstr(",completed,completed"));

  cluster.stop();
}

}  // namespace
}  // namespace mssph::test
