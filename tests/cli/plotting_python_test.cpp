// Commands that end in a Python script check its interpreter before they run anything
// (check_python_modules): with one that cannot import h5py, NumPy and matplotlib, `validate`,
// `figure 3`, `sweep` and `sweep plot` exit 1 at once, name what is missing and how to install it,
// and write nothing. MSSPH_BARE_PYTHON is the test Python without its site packages
// (tests/cli/CMakeLists.txt).
#include "cli_fixture.hpp"

#include <gmock/gmock.h>

#include <fstream>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class PlottingPython : public Cli {
 protected:
  // Runs mssph with MSSPH_PYTHON naming `interpreter`.
  ProcessResult mssph_with(const std::string& interpreter, const std::vector<std::string>& args) const {
    std::vector<std::string> argv{"/usr/bin/env", "MSSPH_PYTHON=" + interpreter, MSSPH_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv, work_.path());
  }

  void expect_stopped_before_any_run(const ProcessResult& r, const std::string& message) const {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr(message));
    EXPECT_THAT(r.err, HasSubstr("apt-get install python3-h5py python3-numpy python3-matplotlib"));
    EXPECT_THAT(r.err, HasSubstr("Nothing was run."));
    EXPECT_EQ(work_entries(), std::vector<std::string>{}) << r.err;
  }
};

TEST_F(PlottingPython, ValidateStopsBeforeItsFirstCase) {
  const ProcessResult r =
      mssph_with(MSSPH_BARE_PYTHON, {"validate", "--quick", "--case", "coupling_step", "--out", "r"});
  expect_stopped_before_any_run(r, "cannot import h5py, numpy, matplotlib");
  EXPECT_THAT(r.err, Not(HasSubstr("validate: [1/1]")));
}

TEST_F(PlottingPython, FigureThreeStopsBeforeItsFirstDrop) {
  const ProcessResult r =
      mssph_with(MSSPH_BARE_PYTHON, {"figure", "3", "--backend", "cpu", "--resolution", "coarse", "--out", "f3"});
  expect_stopped_before_any_run(r, "cannot import h5py, numpy, matplotlib");
  EXPECT_THAT(r.err, Not(HasSubstr("figure 3: run 1 of 3")));
}

// A sweep's metrics and summary import h5py and NumPy alone.
TEST_F(PlottingPython, SweepStopsBeforeItsFirstPoint) {
  const ProcessResult r = mssph_with(
      MSSPH_BARE_PYTHON, {"sweep", MSSPH_SOURCE_DIR "/configs/sweep_viscosity.json", "--out", "s", "--backend", "cpu"});
  expect_stopped_before_any_run(r, "cannot import h5py, numpy;");
}

TEST_F(PlottingPython, SweepPlotStopsBeforeItsScript) {
  std::filesystem::create_directory(work("s"));
  std::ofstream(work("s/sweep.json")) << "{}";
  const ProcessResult r = mssph_with(MSSPH_BARE_PYTHON, {"sweep", "plot", "s"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("cannot import h5py, numpy, matplotlib"));
  EXPECT_THAT(r.err, Not(HasSubstr("Traceback")));
}

// An interpreter that does not start, and one that exits 0 without running the probe.
TEST_F(PlottingPython, AnInterpreterThatRunsNoProbeIsNamed) {
  const ProcessResult none = mssph_with("/nonexistent/python3", {"validate", "--quick", "--case", "coupling_step"});
  expect_stopped_before_any_run(none, "/nonexistent/python3 did not run a Python 3 probe (exit code 127)");
  const ProcessResult idle = mssph_with("/bin/true", {"validate", "--quick", "--case", "coupling_step"});
  expect_stopped_before_any_run(idle, "/bin/true did not run a Python 3 probe (exit code 0)");
}

}  // namespace
}  // namespace mssph::test
