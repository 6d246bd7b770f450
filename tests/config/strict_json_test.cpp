// The strict JSON reader every input file and --set value goes through: what it refuses, with
// which JSON pointer, and which refusals are syntax errors (--set then takes the text as a word).
#include "config/strict_json.hpp"

#include "config_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace mssph {
namespace {

using test::input_error_of;
using testing::HasSubstr;

std::string nested(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(StrictJson, NestingUpToTheLimitIsReadAndOneLevelMoreIsRefusedWithItsPointer) {
  EXPECT_EQ(parse_strict_json(nested(kMaxJsonDepth), "f.json").dump(), nested(kMaxJsonDepth));
  // The object, "a" and 62 arrays inside it make 64 levels: the 63rd array inside is one too many.
  std::string pointer = "/a/1";
  for (std::size_t level = 0; level < kMaxJsonDepth - 2; ++level) pointer += "/0";
  EXPECT_EQ(input_error_of([&] { parse_strict_json("{\"a\": [1, " + nested(kMaxJsonDepth - 1) + "]}", "f.json"); }),
            "f.json: " + pointer + ": arrays and objects nested more than 64 levels deep (mssph's files need a few)");
}

TEST(StrictJson, DuplicateKeysAreFoundInLargeDocuments) {
  std::string text = "{\"k\": [";
  for (int i = 0; i < 100000; ++i) text += (i ? "," : "") + std::string("{\"a\": 1, \"b\": 2}");
  text += ", {\"a\": 1, \"a\": 2}]}";
  EXPECT_EQ(input_error_of([&] { parse_strict_json(text, "big.json"); }),
            "big.json: /k/100000/a: duplicate key 'a' (JSON leaves its meaning undefined; keep one)");
}

TEST(StrictJson, OnlySyntaxErrorsAreJsonSyntaxErrors) {
  EXPECT_THROW(parse_strict_json("cauchy", "--set a"), JsonSyntaxError);
  EXPECT_THROW(parse_strict_json("[1, 2", "--set a"), JsonSyntaxError);
  for (const std::string& strict_only :
       {std::string("{\"a\": 1, \"a\": 2}"), std::string("[1e400]"), nested(kMaxJsonDepth + 1)}) {
    try {
      parse_strict_json(strict_only, "--set a");
      ADD_FAILURE() << strict_only << " was accepted";
    } catch (const JsonSyntaxError& e) {
      ADD_FAILURE() << strict_only << " counts as a syntax error: " << e.what();
    } catch (const InputError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr("--set a: /"));
    }
  }
}

TEST(StrictJson, ASyntaxErrorNamesTheLineAndColumn) {
  EXPECT_THAT(input_error_of([&] { parse_strict_json("{\n  \"a\": 1,\n  \"b\": }", "f.json"); }),
              HasSubstr("f.json:3:8: invalid JSON: "));
}

}  // namespace
}  // namespace mssph
