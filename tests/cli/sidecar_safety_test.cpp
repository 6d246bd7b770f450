// The XDMF sidecars of a run log follow the --out rule: <out>.xdmf is written only by a run that
// takes snapshots and removed (as the stale sidecar of a replaced log) only with --force; the
// unfinished log's <out>.partial.xdmf replaces an existing file only with --force; and no sidecar
// is ever one of the run's inputs.
#include "cli_fixture.hpp"

#include <fstream>

namespace mssph::test {
namespace {

namespace fs = std::filesystem;

using SidecarSafety = Cli;

const std::string kSnapshots = "output/snapshot_interval=0.01";

// O04: a file named like the sidecar of a log without snapshots.
TEST_F(SidecarSafety, ARunWithoutSnapshotsLeavesAnXdmfFileAlone) {
  { std::ofstream(work("o.h5.xdmf")) << "precious"; }
  const ProcessResult r = mssph({"run", kTinyDrop, "--out", work("o.h5"), "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(work("o.h5.xdmf")), "precious");
}

// O05: the scene file itself has the sidecar's name.
TEST_F(SidecarSafety, TheSceneFileIsNeverASidecar) {
  const std::string scene = work("x.h5.xdmf");
  fs::copy_file(kTinyDrop, scene);
  const ProcessResult r = mssph({"run", scene, "--out", work("x.h5"), "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(scene), read_file(kTinyDrop));
  // --force would remove a replaced log's stale sidecar: never the scene.
  expect_refused_and_untouched({"run", scene, "--out", work("x.h5"), "-q", "--force"}, scene, "is the scene file");
  expect_refused_and_untouched({"run", scene, "--out", work("x.h5"), "-q", "--force", "--set", kSnapshots}, scene,
                               "is the scene file");
}

// O08: a file at the unfinished log's sidecar name.
TEST_F(SidecarSafety, AnExistingPartialSidecarIsReplacedOnlyWithForce) {
  const std::string sidecar = work("s.h5.partial.xdmf");
  { std::ofstream(sidecar) << "precious"; }
  const std::vector<std::string> args{"run", kTinyDrop, "--out", work("s.h5"), "-q", "--set", kSnapshots};
  expect_refused_and_untouched(args, sidecar, "exists; pass --force");
  EXPECT_FALSE(fs::exists(work("s.h5.partial")));
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  const ProcessResult r = mssph(forced);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(work("s.h5.xdmf")).find("s.h5:/snapshots/"), std::string::npos);
  EXPECT_FALSE(fs::exists(sidecar)) << "the unfinished log's sidecar goes once the log is published";
}

}  // namespace
}  // namespace mssph::test
