// --gpus: one point per listed GPU at a time, each point's process seeing only its GPU through
// CUDA_VISIBLE_DEVICES. Checked on machines without GPUs through the documented test hook
// MSSPH_SWEEP_RUNNER: a script that records what each point was started with, then runs it on the
// cpu backend.
#include "sweep_cli_fixture.hpp"

#include <gmock/gmock.h>

#include <cstdlib>
#include <fstream>
#include <map>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

struct Interval {
  long long start = 0;
  long long end = 0;
};

class SweepGpus : public SweepCli {
 protected:
  // Returns, per CUDA_VISIBLE_DEVICES value, the [start, end] wall-clock intervals of its points.
  std::map<std::string, std::vector<Interval>> run_with_gpus(const std::string& gpus, std::size_t expected_points) {
    const std::string record = (hook_dir_ / "record.txt").string();
    const std::string hook = (hook_dir_ / "fake_gpu_runner.sh").string();
    std::ofstream(hook) << "#!/bin/bash\n"
                           "# The point's arguments with --backend cuda made cpu; one line when it starts and ends.\n"
                           "args=()\n"
                           "for a in \"$@\"; do [[ $a == cuda ]] && a=cpu; args+=(\"$a\"); done\n"
                           "echo \"start $$ ${CUDA_VISIBLE_DEVICES-unset} $(date +%s%N)\" >> '" +
                               record +
                               "'\n"
                               "'" MSSPH_BINARY
                               "' \"${args[@]}\"\n"
                               "code=$?\n"
                               "echo \"end $$ ${CUDA_VISIBLE_DEVICES-unset} $(date +%s%N)\" >> '" +
                               record +
                               "'\n"
                               "exit $code\n";
    std::filesystem::permissions(hook, std::filesystem::perms::owner_all);
    setenv("MSSPH_SWEEP_RUNNER", hook.c_str(), 1);
    const ProcessResult r = mssph({"sweep", tiny_product_sweep(), "--out", out(), "--backend", "cuda", "--gpus", gpus});
    unsetenv("MSSPH_SWEEP_RUNNER");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    last_err_ = r.err;
    std::map<std::string, Interval> by_process;
    std::map<std::string, std::string> gpu_of;
    std::istringstream lines(read_file(record));
    for (std::string what, pid, gpu; lines >> what >> pid >> gpu;) {
      long long ns = 0;
      lines >> ns;
      (what == "start" ? by_process[pid].start : by_process[pid].end) = ns;
      gpu_of[pid] = gpu;
    }
    EXPECT_EQ(by_process.size(), expected_points);
    std::map<std::string, std::vector<Interval>> out;
    for (const auto& [pid, interval] : by_process) out[gpu_of[pid]].push_back(interval);
    return out;
  }
  TempDir hook_dir_;
  std::string last_err_;
};

TEST_F(SweepGpus, EachPointSeesOneListedGpuAndNoGpuRunsTwoAtOnce) {
  const auto by_gpu = run_with_gpus("0,1", 4);
  std::vector<std::string> gpus;
  for (const auto& [gpu, intervals] : by_gpu) gpus.push_back(gpu);
  EXPECT_EQ(gpus, (std::vector<std::string>{"0", "1"})) << "points go to both GPUs and nowhere else";
  EXPECT_THAT(last_err_, HasSubstr(") on GPU 1 started"));
  for (const auto& [gpu, intervals] : by_gpu) {
    for (std::size_t a = 0; a < intervals.size(); ++a) {
      EXPECT_LT(intervals[a].start, intervals[a].end);
      for (std::size_t b = a + 1; b < intervals.size(); ++b) {
        const bool apart = intervals[a].end <= intervals[b].start || intervals[b].end <= intervals[a].start;
        EXPECT_TRUE(apart) << "two points at once on GPU " << gpu;
      }
    }
  }
  EXPECT_EQ(csv_column("state"), std::vector<std::string>(4, "completed"));
}

TEST_F(SweepGpus, AGpuListIsUsedAsGiven) {
  const auto by_gpu = run_with_gpus("3", 4);
  ASSERT_EQ(by_gpu.size(), 1u);
  EXPECT_EQ(by_gpu.begin()->first, "3");
}

}  // namespace
}  // namespace mssph::test
