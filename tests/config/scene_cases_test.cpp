// Every variant of tests/config/data/scene_cases.json, written to a file and loaded through
// load_scene. check_scene_schema.py validates the same variants against
// configs/scene.schema.json, so the loader and the schema are held to the same inputs.
#include "config/scene_loader.hpp"

#include "config_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

namespace mssph {
namespace {

using nlohmann::json;
using testing::HasSubstr;
using testing::StartsWith;

const std::string kData = std::string(MSSPH_SOURCE_DIR) + "/tests/config/data/";

struct SceneCase {
  std::string name;
  json document;         // the base scene with the case's patch applied
  std::string pointer;   // rejected cases: where the loader must point
  std::string expected;  // rejected cases: what its message must say
};

std::vector<SceneCase> read_cases(const std::string& list) {
  const json cases = test::read_json_file(kData + "scene_cases.json");
  const json base = test::read_json_file(kData + "base_scene.json");
  std::vector<SceneCase> out;
  for (const json& c : cases.at(list)) {
    out.push_back({c.at("name"), base.patch(c.at("patch")), c.value("pointer", ""), c.value("expected", "")});
  }
  return out;
}

// gtest names: the case names are already identifiers.
std::string case_name(const testing::TestParamInfo<SceneCase>& info) { return info.param.name; }

// How gtest shows a case (in test listings and ctest names).
void PrintTo(const SceneCase& c, std::ostream* out) { *out << c.name; }

// Each variant becomes a file of its own so the message names a real file, as for a user.
test::TempFile write_case(const SceneCase& c) { return {c.name + ".json", c.document.dump(2)}; }

class AcceptedScene : public testing::TestWithParam<SceneCase> {};

TEST_P(AcceptedScene, Loads) {
  const test::TempFile file = write_case(GetParam());
  EXPECT_NO_THROW(load_scene(file.path()));
}

INSTANTIATE_TEST_SUITE_P(SceneCases, AcceptedScene, testing::ValuesIn(read_cases("accepted")), case_name);

class RejectedScene : public testing::TestWithParam<SceneCase> {};

TEST_P(RejectedScene, FailsNamingTheFileThePointerAndWhatWasExpected) {
  const SceneCase& c = GetParam();
  ASSERT_FALSE(c.pointer.empty()) << "a rejected case needs a \"pointer\"";
  ASSERT_FALSE(c.expected.empty()) << "a rejected case needs an \"expected\" message";
  const test::TempFile file = write_case(c);
  const std::string message = test::input_error_of([&] { load_scene(file.path()); });
  EXPECT_THAT(message, StartsWith(file.path() + ": " + c.pointer + ": "));
  EXPECT_THAT(message, HasSubstr(c.expected));
}

INSTANTIATE_TEST_SUITE_P(SceneCases, RejectedScene, testing::ValuesIn(read_cases("rejected")), case_name);

}  // namespace
}  // namespace mssph
