// Bad input to `mssph run`: exit code 2, an error that names the file and the key or argument,
// and nothing written (the working directory, where the default output would go, stays empty).
#include "backend_factory/backend_factory.hpp"
#include "cli_fixture.hpp"
#include "util/build_info.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

namespace mssph::test {
namespace {

class BadInput : public Cli {
 protected:
  // Runs mssph with `args` and checks the outcome; `names` must all appear on stderr.
  void expect_rejected(const std::vector<std::string>& args, const std::vector<std::string>& names) {
    const std::vector<std::string> before = work_entries();
    const ProcessResult r = mssph(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const std::string& name : names) EXPECT_NE(r.err.find(name), std::string::npos) << name << " in\n" << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(work_entries(), before) << "bad input must not leave output behind";
  }
};

TEST_F(BadInput, MissingSceneFile) {
  expect_rejected({"run", data_file("no_such_scene.json")}, {"no_such_scene.json"});
}

TEST_F(BadInput, InvalidJson) {
  expect_rejected({"run", data_file("bad_syntax.json")}, {"bad_syntax.json:", "invalid JSON"});
}

TEST_F(BadInput, UnknownKey) {
  expect_rejected({"run", data_file("unknown_key.json")}, {"unknown_key.json", "/simulation/time_step"});
}

TEST_F(BadInput, SetValueOutOfRange) {
  expect_rejected({"run", kTinyDrop, "--set", "simulation/dt=-1"}, {"tiny_drop.json", "/simulation/dt"});
}

TEST_F(BadInput, SetPathWithoutParent) {
  expect_rejected({"run", kTinyDrop, "--set", "simulation_settings/dt=1e-4"}, {"simulation_settings"});
}

// A value the JSON library cannot hold (it requires UTF-8), which used to end in a raw library
// error and exit 1; the corpus manifest cannot hold such bytes, so the case lives here.
TEST_F(BadInput, SetValueThatIsNotUtf8) {
  expect_rejected({"run", kTinyDrop, "--set", "bodies/ball/description=\xff\xfe"},
                  {"tiny_drop.json", "--set /bodies/ball/description=...", "not valid UTF-8"});
}

TEST_F(BadInput, SetWithoutValue) {
  expect_rejected({"run", kTinyDrop, "--set", "simulation/dt"}, {"--set simulation/dt", "PATH=VALUE"});
}

TEST_F(BadInput, UnknownBackend) {
  expect_rejected({"run", kTinyDrop, "--backend", "quantum"}, {"--backend", "quantum"});
}

TEST_F(BadInput, BackendNotBuilt) {
  const std::vector<std::string> built = available_backends();
  bool tried = false;
  for (const std::string& name : backend_names()) {
    if (std::find(built.begin(), built.end(), name) != built.end()) continue;
    SCOPED_TRACE(name);
    expect_rejected({"run", kTinyDrop, "--backend", name}, {"--backend " + std::string(name)});
    tried = true;
  }
  if (!tried) GTEST_SKIP() << "this build has every backend";
}

// A build with the CUDA backend on a machine without a GPU (as CI): asking for it is bad input
// that says what to use instead.
TEST_F(BadInput, CudaWithoutADevice) {
  if (!build_info().cuda_backend) GTEST_SKIP() << "built without the CUDA backend (BackendNotBuilt covers this build)";
  if (!gpu_devices().empty()) GTEST_SKIP() << "a CUDA device is present";
  expect_rejected({"run", kTinyDrop, "--backend", "cuda"}, {"--backend cuda", "no CUDA device", "--backend cpu"});
}

TEST_F(BadInput, OutIsADirectory) {
  std::filesystem::create_directory(work("runs"));
  expect_rejected({"run", kTinyDrop, "--out", work("runs")}, {"--out " + work("runs"), "is a directory"});
  expect_rejected({"run", kTinyDrop, "--out", work("runs") + "/"}, {"is a directory"});
}

TEST_F(BadInput, OutUnderARegularFile) {
  { std::ofstream(work("notes.txt")) << "not a directory"; }
  expect_rejected({"run", kTinyDrop, "--out", work("notes.txt/sub/run.h5")}, {work("notes.txt"), "not a directory"});
}

TEST_F(BadInput, OutInAnUnwritableDirectory) {
  if (geteuid() == 0) GTEST_SKIP() << "running as root, which may write anywhere";
  std::filesystem::create_directory(work("locked"));
  std::filesystem::permissions(work("locked"), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  expect_rejected({"run", kTinyDrop, "--out", work("locked/new/run.h5")}, {work("locked"), "cannot create files"});
  std::filesystem::permissions(work("locked"), std::filesystem::perms::owner_all);  // so it can be removed
}

// tiny_drop with its "name" replaced, written into the working directory as `file`.
std::string tiny_drop_named(const std::string& directory, const std::string& file, const std::string& name) {
  nlohmann::json scene = read_json(kTinyDrop);
  scene["name"] = name;
  const std::string path = directory + "/" + file;
  std::ofstream(path) << scene.dump(2);
  return path;
}

// The default log path (results/runs/<scene>_<backend>.h5) would be cut at the NUL, so that the
// run took another file for its own.
TEST_F(BadInput, ASceneNameWithANulCharacter) {
  const std::string scene = tiny_drop_named(work_.path().string(), "nul.json", std::string("ok\0base", 7));
  expect_rejected({"run", scene}, {"nul.json", "/name", "control characters"});
}

// A name too long for a file name: refused before the default path's folders are created.
TEST_F(BadInput, ASceneNameTooLongForAFileName) {
  const std::string scene = tiny_drop_named(work_.path().string(), "long.json", std::string(300, 'n'));
  expect_rejected({"run", scene}, {"results/runs/nnn", "255 bytes"});
}

// An empty --out or --record-device is a mistake, not a request for the default (or for none).
TEST_F(BadInput, AnEmptyOutputPath) {
  expect_rejected({"run", kTinyDrop, "--out", ""}, {"--out", "expected a file name"});
  expect_rejected({"run", kTinyDrop, "--out", work("o.h5"), "--record-device", ""},
                  {"--record-device", "expected a file name"});
}

// An attribute name HDF5 cannot store (its object header messages hold at most 64 KiB).
TEST_F(BadInput, ATagNameTooLongForAnAttribute) {
  expect_rejected({"run", kTinyDrop, "--out", work("o.h5"), "--tag", std::string(70000, 'n') + "=1"},
                  {"--tag nnnn", "at most 255 bytes"});
}

// A recorded trajectory that exists but is no regular file says what it is; a FIFO is not opened
// (which would wait for a writer forever).
TEST_F(BadInput, ARecordedTrajectoryThatIsNoRegularFile) {
  ASSERT_EQ(mkfifo(work("fifo.csv").c_str(), 0644), 0);
  std::filesystem::create_directory(work("folder.csv"));
  const std::vector<std::pair<std::string, std::string>> cases{
      {work("fifo.csv"), "is a FIFO"}, {work("folder.csv"), "is a directory"}, {"/dev/null", "is a device"}};
  for (const auto& [file, what] : cases) {
    const std::string trajectory = nlohmann::json{{"source", "recorded"}, {"file", file}}.dump();
    expect_rejected({"run", kTinyDrop, "--out", work("o.h5"), "--set", "proxy/trajectory=" + trajectory},
                    {file + ": " + what});
  }
}

}  // namespace
}  // namespace mssph::test
