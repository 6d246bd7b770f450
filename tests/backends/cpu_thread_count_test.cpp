// The cpu backend's results do not depend on how many OpenMP threads run it: each particle's sums
// are taken by one thread, whichever part of the cost-balanced split holds it
// (kernels/cpu/particle_partition.hpp), so one thread and three give the same bits. Three, not
// two, so that the parts differ from a halving; CI runs each test on one thread, so without this
// test no split of a real scene would run there.
#include "backend_fixtures.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <memory>
#include <string>

namespace mssph::testing {
namespace {

constexpr int kSteps = 200;  // 0.05 s at dt 0.25 ms: the sphere falls, the grid is rebuilt several times

// The OpenMP thread count for the lifetime of the guard, restored after it even if a run throws.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : before_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~ThreadCount() { omp_set_num_threads(before_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

  // How many threads a parallel region gets now (OMP_DYNAMIC or OMP_THREAD_LIMIT may give fewer).
  static int in_a_region() {
    int team = 0;
#pragma omp parallel
    {
#pragma omp single
      team = omp_get_num_threads();
    }
    return team;
  }

 private:
  int before_;
};

ParticleSnapshot run(const ParticleSetup& setup) {
  const std::unique_ptr<Backend> backend = make_backend("cpu", setup);
  for (int i = 0; i < kSteps; ++i) backend->step();
  return backend->snapshot();
}

class CpuThreadCount : public ::testing::TestWithParam<std::string> {};

TEST_P(CpuThreadCount, OneThreadAndThreeGiveTheSameBits) {
  // 2 cm, not CI's usual 4 cm: 14-17k particles, so that each thread's part holds many cells.
  const ParticleSetup setup = validation::shipped_scene("sphere_drop_" + GetParam() + ".json", 0.02, kSteps * 0.00025);
  ParticleSnapshot one, three;
  {
    const ThreadCount threads(1);
    one = run(setup);
  }
  {
    const ThreadCount threads(3);
    if (ThreadCount::in_a_region() != 3) GTEST_SKIP() << "this OpenMP runtime gives a region fewer than 3 threads";
    three = run(setup);
  }
  EXPECT_EQ(one.position, three.position);
  EXPECT_EQ(one.velocity, three.velocity);
  EXPECT_EQ(one.density, three.density);
  EXPECT_EQ(one.pressure, three.pressure);
}

INSTANTIATE_TEST_SUITE_P(Media, CpuThreadCount, ::testing::Values("fluid", "rigid", "deformable"),
                         [](const auto& test) { return test.param; });

}  // namespace
}  // namespace mssph::testing
