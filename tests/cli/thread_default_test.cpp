// The OpenMP defaults of `mssph run` on a machine that may be busy: threads from the CPUs other
// work leaves free, and passive waiting unless the environment chose a policy. Before, a run took
// a thread per usable CPU and spinning waits, which beside two busy loops made a 227-particle run
// take up to 33 s instead of 0.1 s (results/decisions/049-openmp-on-a-busy-host.md).
#include "cli_fixture.hpp"

#include <cstdlib>
#include <optional>

namespace mssph::test {
namespace {

// Sets (or, with nullopt, removes) an environment variable for the test's children, and puts back
// what was there when it ends.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* previous = std::getenv(name)) previous_ = previous;
    if (value) {
      setenv(name, value->c_str(), 1);
    } else {
      unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    if (previous_) {
      setenv(name_, previous_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> previous_;
};

using ThreadDefault = Cli;

TEST_F(ThreadDefault, ThreadsComeFromTheFreeCpusAndWaitingIsPassive) {
  const ScopedEnvironment threads("OMP_NUM_THREADS", std::nullopt);
  const ScopedEnvironment policy("OMP_WAIT_POLICY", std::nullopt);
  const ProcessResult r = mssph({"run", kCorpusBase, "--backend", "cpu", "--out", work("o.h5")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(" threads (free CPUs: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(", OMP_WAIT_POLICY passive\n"), std::string::npos) << r.err;
}

TEST_F(ThreadDefault, ThePolicyTheUserSetIsKept) {
  const ScopedEnvironment policy("OMP_WAIT_POLICY", "active");
  const ProcessResult r = mssph({"run", kCorpusBase, "--backend", "cpu", "--threads", "1", "--out", work("o.h5")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 threads (--threads), OMP_WAIT_POLICY active\n"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mssph::test
