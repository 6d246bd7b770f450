// SIGINT and SIGTERM before a run's log exists: while the scene loads (here from a FIFO nobody
// writes to) and while millions of particles are set up, for a run and a dry run. The process
// ends within 2 s of the signal with 128 + its number, says so, and leaves nothing behind.
#include "cli_fixture.hpp"

#include <sys/stat.h>

#include <csignal>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

// 3.6 million particles: minutes of set-up on a 2-core machine.
const std::string kMillionsOfParticles = "simulation/particle_spacing=0.002";

class SignalBeforeRun : public Cli {
 protected:
  // Sends `signal` to `run` after `delay` and returns how it ended and how long after the signal.
  std::pair<ProcessResult, double> signal_after(ChildProcess& run, std::chrono::milliseconds delay, int signal) const {
    std::this_thread::sleep_for(delay);
    EXPECT_TRUE(run.running()) << run.stderr_so_far();
    const auto sent = std::chrono::steady_clock::now();
    run.send(signal);
    const ProcessResult r = run.wait(20s);
    return {r, std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
  }

  void expect_ended_by(const ProcessResult& r, double seconds, int signal, const std::string& name) const {
    EXPECT_FALSE(r.timed_out) << "still running 20 s after " << name;
    EXPECT_EQ(r.exit_code, 128 + signal) << r.err;
    EXPECT_LT(seconds, 2.0) << name << " answered after " << seconds << " s";
    EXPECT_NE(r.err.find("error: " + name + " before the run started; nothing was written"), std::string::npos)
        << r.err;
    EXPECT_TRUE(work_entries().empty());
  }

  TempDir inputs_;
};

// Opening a FIFO waits for a writer; the handlers, installed with SA_RESTART, restarted that wait
// after every signal.
TEST_F(SignalBeforeRun, SigintWhileTheSceneLoadsFromAFifo) {
  const std::string fifo = (inputs_ / "scene.fifo").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  auto run = start({"run", fifo, "-q", "--backend", "cpu", "--out", work("o.h5")});
  const auto [r, seconds] = signal_after(*run, 500ms, SIGINT);
  expect_ended_by(r, seconds, SIGINT, "SIGINT");
}

// The signal was acted on only once the set-up was over, minutes later.
TEST_F(SignalBeforeRun, SigtermDuringTheSetUpOfMillionsOfParticles) {
  auto run =
      start({"run", kCorpusBase, "-q", "--backend", "cpu", "--out", work("o.h5"), "--set", kMillionsOfParticles});
  const auto [r, seconds] = signal_after(*run, 1500ms, SIGTERM);
  expect_ended_by(r, seconds, SIGTERM, "SIGTERM");
}

// A dry run printed its plan and exited 0 whatever signal came during its set-up.
TEST_F(SignalBeforeRun, SigintDuringADryRunsSetUp) {
  auto run = start({"run", kCorpusBase, "--dry-run", "--backend", "cpu", "--set", kMillionsOfParticles});
  const auto [r, seconds] = signal_after(*run, 1500ms, SIGINT);
  expect_ended_by(r, seconds, SIGINT, "SIGINT");
  EXPECT_EQ(r.out, "") << "no plan for a dry run cut short";
}

}  // namespace
}  // namespace mssph::test
