// The scripts of --emit-slurm: what each #SBATCH line and command says, and that bash parses them.
#include "sweep/slurm_script.hpp"
#include "child_process.hpp"
#include "temp_dir.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

sweep::SlurmOptions options(const TempDir& dir) {
  sweep::SlurmOptions o;
  o.program = "/opt/mssph/bin/mssph";
  o.sweep_file = "/home/u/it's here/sweep.json";  // a quote and a space to survive
  o.directory = dir.path().string();
  o.sweep_name = "stiffness";
  o.backend = "cuda";
  o.overrides = {"simulation/particle_spacing=0.04"};
  o.tasks = 8;
  return o;
}

TEST(SlurmScript, ArrayScriptRunsShardKOfNInEveryTask) {
  TempDir dir;
  sweep::SlurmOptions o = options(dir);
  o.partition = "gpu";
  o.gpus_per_task = 1;
  o.max_parallel = 2;
  o.time_limit = "01:00:00";
  o.sbatch_options = {"--account=lab"};
  const std::string text = sweep::array_script_text(o);
  EXPECT_THAT(text, HasSubstr("#SBATCH --array=0-7%2\n"));
  EXPECT_THAT(text, HasSubstr("#SBATCH --partition=gpu\n"));
  EXPECT_THAT(text, HasSubstr("#SBATCH --gpus-per-task=1\n"));
  EXPECT_THAT(text, HasSubstr("#SBATCH --time=01:00:00\n"));
  EXPECT_THAT(text, HasSubstr("#SBATCH --account=lab\n"));
  EXPECT_THAT(text, HasSubstr("#SBATCH --output=" + o.directory + "/slurm/logs/shard-%a.out\n"));
  EXPECT_THAT(text,
              HasSubstr("exec '/opt/mssph/bin/mssph' sweep '/home/u/it'\\''s here/sweep.json' --out '" + o.directory +
                        "' --backend 'cuda' --shard \"${SLURM_ARRAY_TASK_ID}/8\" --set "
                        "'simulation/particle_spacing=0.04'\n"));
  EXPECT_THAT(text, Not(HasSubstr("--retry-failed")));
}

TEST(SlurmScript, MergeRunsAfterTheWholeArray) {
  TempDir dir;
  const sweep::SlurmOptions o = options(dir);
  EXPECT_THAT(sweep::merge_script_text(o),
              HasSubstr("exec '/opt/mssph/bin/mssph' sweep merge '" + o.directory + "'\n"));
  const sweep::SlurmScripts scripts = sweep::write_slurm_scripts(o);
  const std::string submit = read_file(scripts.submit_script);
  EXPECT_THAT(submit, HasSubstr("--dependency=afterany:${array_job}"));
  EXPECT_TRUE(std::filesystem::is_directory(o.directory + "/slurm/logs")) << "sbatch does not create --output folders";
  for (const std::string& script : {scripts.array_script, scripts.merge_script, scripts.submit_script}) {
    const ProcessResult r = run_process({"/bin/bash", "-n", script});
    EXPECT_EQ(r.exit_code, 0) << script << ":\n" << r.err;
    EXPECT_NE(std::filesystem::status(script).permissions() & std::filesystem::perms::owner_exec,
              std::filesystem::perms::none);
  }
}

}  // namespace
}  // namespace mssph::test
