// The malformed-input corpus (tests/corpus/cases.json): every scene file, recorded trajectory
// and command line there must be refused with its exit code and a message holding its fragment
// (which names the file and the JSON path or row), with nothing written.
#include "cli_fixture.hpp"

#include <fstream>
#include <ostream>
#include <set>

namespace mssph::test {
namespace {

const std::string kCorpus = MSSPH_SOURCE_DIR "/tests/corpus/";

struct CorpusCase {
  std::string file;
  std::vector<std::string> args;
  int exit_code = 0;
  std::string message;
  std::string why;
};

// What gtest prints for a case (instead of its bytes).
void PrintTo(const CorpusCase& c, std::ostream* out) { *out << c.file << " (" << c.why << ")"; }

std::vector<CorpusCase> load_cases() {
  const nlohmann::json manifest = read_json(kCorpus + "cases.json");
  std::vector<CorpusCase> cases;
  for (const nlohmann::json& c : manifest.at("cases")) {
    cases.push_back(
        {c.at("file"), c.at("args").get<std::vector<std::string>>(), c.at("exit"), c.at("message"), c.at("why")});
  }
  return cases;
}

// The test's name: the file's stem, and the arguments when the file is the valid base scene;
// another file run with arguments too gets "_with_set".
std::string case_name(const ::testing::TestParamInfo<CorpusCase>& info) {
  std::string name = std::filesystem::path(info.param.file).stem().string();
  if (name == "ok_base") {
    name = "set_" + std::to_string(info.index);
  } else if (!info.param.args.empty()) {
    name += "_with_set";
  }
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

class Corpus : public Cli, public ::testing::WithParamInterface<CorpusCase> {};

TEST_P(Corpus, IsRefusedWithItsExitCodeAndMessage) {
  const CorpusCase& c = GetParam();
  std::vector<std::string> args{"run", kCorpus + c.file, "--out", work("out.h5"), "-q"};
  args.insert(args.end(), c.args.begin(), c.args.end());
  const ProcessResult r = mssph(args);
  EXPECT_EQ(r.exit_code, c.exit_code) << c.why << "\n" << r.err;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << c.why << ": expected \"" << c.message << "\" in\n" << r.err;
  EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << r.err;
  if (c.exit_code == 2) {
    EXPECT_TRUE(work_entries().empty()) << "bad input must not leave output behind";
  }
}

INSTANTIATE_TEST_SUITE_P(Inputs, Corpus, ::testing::ValuesIn(load_cases()), case_name);

// The corpus must stay a corpus: at least 40 malformed files, each used by a case.
TEST(CorpusManifest, CoversEveryFileInTheCorpus) {
  std::set<std::string> listed;
  for (const CorpusCase& c : load_cases()) listed.insert(c.file);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kCorpus)) {
    if (!entry.is_regular_file() || entry.path().filename() == "cases.json") continue;
    const std::string relative = std::filesystem::relative(entry.path(), kCorpus).string();
    if (relative.rfind("trajectories/", 0) == 0) {
      ++files;  // used through the scene that replays it (scenes/recorded_<name>.json)
      continue;
    }
    EXPECT_TRUE(listed.count(relative)) << relative << " is in the corpus but no case uses it";
    if (relative != "scenes/ok_base.json") ++files;
  }
  EXPECT_GE(files, 40u);
}

}  // namespace
}  // namespace mssph::test
