// Commands that end in a Python script check its interpreter before they run anything
// (check_plotting_python): with one that cannot import h5py, NumPy and matplotlib, `validate`,
// `figure 3` and `sweep` exit 1 at once, name what is missing and how to install it, and write
// nothing.
#include "cli_fixture.hpp"

#include <gmock/gmock.h>

#include <fstream>

namespace mssph::test {
namespace {

using ::testing::HasSubstr;

class PlottingPython : public Cli {
 protected:
  // Runs mssph with MSSPH_PYTHON naming `interpreter`.
  ProcessResult mssph_with(const std::string& interpreter, const std::vector<std::string>& args) const {
    std::vector<std::string> argv{"/usr/bin/env", "MSSPH_PYTHON=" + interpreter, MSSPH_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv, work_.path());
  }

  // The test's Python without its site packages (-S): the standard library alone.
  std::string bare_python() {
    const std::string path = (tools_ / "bare_python").string();
    std::ofstream(path) << "#!/bin/sh\nexec " MSSPH_PYTHON " -S \"$@\"\n";
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path;
  }

  void expect_stopped_before_any_run(const ProcessResult& r, const std::string& missing) const {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("cannot import " + missing));
    EXPECT_THAT(r.err, HasSubstr("apt-get install python3-h5py python3-numpy python3-matplotlib"));
    EXPECT_THAT(r.err, HasSubstr("Nothing was run."));
    EXPECT_EQ(work_entries(), std::vector<std::string>{}) << r.err;
  }

  TempDir tools_;
};

TEST_F(PlottingPython, ValidateStopsBeforeItsFirstCase) {
  const ProcessResult r = mssph_with(bare_python(), {"validate", "--quick", "--case", "coupling_step", "--out", "r"});
  expect_stopped_before_any_run(r, "h5py, numpy, matplotlib");
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("validate: [1/1]")));
}

TEST_F(PlottingPython, FigureThreeStopsBeforeItsFirstDrop) {
  const ProcessResult r =
      mssph_with(bare_python(), {"figure", "3", "--backend", "cpu", "--resolution", "coarse", "--out", "f3"});
  expect_stopped_before_any_run(r, "h5py, numpy, matplotlib");
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("figure 3: run 1 of 3")));
}

TEST_F(PlottingPython, SweepStopsBeforeItsFirstPoint) {
  const ProcessResult r = mssph_with(
      bare_python(), {"sweep", MSSPH_SOURCE_DIR "/configs/sweep_viscosity.json", "--out", "s", "--backend", "cpu"});
  expect_stopped_before_any_run(r, "h5py, numpy, matplotlib");
}

TEST_F(PlottingPython, AnInterpreterThatDoesNotStartIsNamed) {
  const ProcessResult r = mssph_with("/nonexistent/python3", {"validate", "--quick", "--case", "coupling_step"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("/nonexistent/python3 did not run (exit code 127)"));
  EXPECT_EQ(work_entries(), std::vector<std::string>{}) << r.err;
}

}  // namespace
}  // namespace mssph::test
