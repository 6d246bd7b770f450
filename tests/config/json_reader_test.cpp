// JsonReader: intervals, unknown-key suggestions and the "<file>: <pointer>: <what was
// expected>" form of every error.
#include "config/json_reader.hpp"

#include "config_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mssph {
namespace {

using nlohmann::json;
using test::input_error_of;
using testing::HasSubstr;
using testing::Not;
using testing::StartsWith;

TEST(Interval, DescribesEachKindOfBound) {
  EXPECT_EQ(Interval::any().describe(), "finite");
  EXPECT_EQ(Interval::positive().describe(), "> 0");
  EXPECT_EQ(Interval::non_negative().describe(), ">= 0");
  EXPECT_EQ(Interval::at_least(2.5).describe(), ">= 2.5");
  EXPECT_EQ(Interval::open(-1.0, 0.5).describe(), "in (-1, 0.5)");
  EXPECT_EQ(Interval::closed(1.0, 16.0).describe(), "in [1, 16]");
  EXPECT_EQ((Interval{0.0, 0.25, false, true}).describe(), "in [0, 0.25)");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ((Interval{-inf, 3.0, false, true}).describe(), "< 3");
  EXPECT_EQ((Interval{-inf, 3.0, false, false}).describe(), "<= 3");
}

TEST(Interval, OpenEndsExcludeAndClosedEndsIncludeTheBound) {
  const Interval open = Interval::open(-1.0, 0.5);
  EXPECT_FALSE(open.contains(-1.0));
  EXPECT_TRUE(open.contains(std::nextafter(-1.0, 0.0)));
  EXPECT_TRUE(open.contains(0.0));
  EXPECT_TRUE(open.contains(std::nextafter(0.5, 0.0)));
  EXPECT_FALSE(open.contains(0.5));

  const Interval closed = Interval::closed(1.0, 16.0);
  EXPECT_TRUE(closed.contains(1.0));
  EXPECT_TRUE(closed.contains(16.0));
  EXPECT_FALSE(closed.contains(std::nextafter(1.0, 0.0)));
  EXPECT_FALSE(closed.contains(std::nextafter(16.0, 17.0)));

  EXPECT_FALSE(Interval::positive().contains(0.0));
  EXPECT_TRUE(Interval::non_negative().contains(0.0));
}

TEST(Interval, NoIntervalContainsNanOrInfinity) {
  // A number that overflows a double parses to infinity; it must fail every range check.
  for (const Interval& range : {Interval::any(), Interval::positive(), Interval::at_least(0.0)}) {
    EXPECT_FALSE(range.contains(std::numeric_limits<double>::quiet_NaN())) << range.describe();
    EXPECT_FALSE(range.contains(std::numeric_limits<double>::infinity())) << range.describe();
    EXPECT_FALSE(range.contains(-std::numeric_limits<double>::infinity())) << range.describe();
  }
}

TEST(JsonPointer, EscapesTildeAndSlash) {
  EXPECT_EQ(escape_pointer_token("plain"), "plain");
  EXPECT_EQ(escape_pointer_token("a/b"), "a~1b");
  EXPECT_EQ(escape_pointer_token("a~b"), "a~0b");
  EXPECT_EQ(escape_pointer_token("~/"), "~0~1");
}

TEST(JsonReader, AllowOnlySuggestsTheClosestKeyForANearMiss) {
  const json doc = {{"particle_spacng", 0.02}};
  const JsonReader reader(doc, "scene.json", "/simulation");
  EXPECT_EQ(input_error_of([&] {
              reader.allow_only({"dt", "duration", "particle_spacing"});
            }),
            "scene.json: /simulation/particle_spacng: unknown key 'particle_spacng' (did you mean "
            "'particle_spacing'?)");
}

TEST(JsonReader, AllowOnlyListsTheAllowedKeysWhenNoneIsClose) {
  const json doc = {{"colour", "red"}};
  const JsonReader reader(doc, "scene.json", "/bodies/a");
  const std::string message = input_error_of([&] { reader.allow_only({"kind", "shape"}); });
  EXPECT_EQ(message, "scene.json: /bodies/a/colour: unknown key 'colour'; allowed keys: kind shape");
}

TEST(JsonReader, AllowOnlyAcceptsAllowedKeysAndRejectsANonObject) {
  const json doc = {{"kind", "fluid"}};
  EXPECT_NO_THROW(JsonReader(doc, "f").allow_only({"kind", "shape"}));
  const json array = json::array({1, 2});
  EXPECT_THAT(input_error_of([&] { JsonReader(array, "f", "/bodies").allow_only({"kind"}); }),
              StartsWith("f: /bodies: expected an object, got array [1,2]"));
}

TEST(JsonReader, TypeErrorsNameTheFileThePointerAndTheExpectedType) {
  const json doc = json::parse(R"({"simulation": {"dt": "fast", "flag": 1, "kind": 3, "name": 2}})");
  const JsonReader simulation = JsonReader(doc, "configs/x.json").child("simulation");
  EXPECT_EQ(input_error_of([&] { simulation.number("dt", Interval::positive()); }),
            "configs/x.json: /simulation/dt: expected a number > 0, got string \"fast\"");
  EXPECT_EQ(input_error_of([&] { simulation.boolean_or("flag", false); }),
            "configs/x.json: /simulation/flag: expected true or false, got number 1");
  EXPECT_EQ(input_error_of([&] {
              simulation.choice("kind", {"fluid", "rigid"});
            }),
            "configs/x.json: /simulation/kind: expected one of \"fluid\", \"rigid\", got number 3");
  EXPECT_EQ(input_error_of([&] { simulation.string("name"); }),
            "configs/x.json: /simulation/name: expected a string, got number 2");
}

TEST(JsonReader, RangeErrorsGiveTheIntervalAndTheValue) {
  const json doc = {{"nu", 0.5}, {"layers", 17}};
  const JsonReader reader(doc, "f.json", "/m");
  EXPECT_EQ(input_error_of([&] { reader.number("nu", Interval::open(-1.0, 0.5)); }),
            "f.json: /m/nu: expected a number in (-1, 0.5), got 0.5");
  EXPECT_EQ(input_error_of([&] { reader.integer_or("layers", 2, Interval::closed(1, 16)); }),
            "f.json: /m/layers: expected an integer in [1, 16], got number 17");
}

TEST(JsonReader, MissingRequiredKeyIsNamed) {
  const json doc = json::object();
  EXPECT_EQ(input_error_of([&] { JsonReader(doc, "f.json", "/simulation").number("dt"); }),
            "f.json: /simulation/dt: missing required key");
  EXPECT_EQ(input_error_of([&] { JsonReader(doc, "f.json").child("bodies"); }),
            "f.json: /bodies: missing required key");
}

TEST(JsonReader, OptionalKeysFallBackOnlyWhenAbsent) {
  const json doc = {{"x", 2.0}};
  const JsonReader reader(doc, "f");
  EXPECT_EQ(reader.number_or("x", 5.0), 2.0);
  EXPECT_EQ(reader.number_or("y", 5.0), 5.0);
  EXPECT_EQ(reader.integer_or("y", 7), 7);
  EXPECT_EQ(reader.string_or("y", "default"), "default");
  EXPECT_FALSE(reader.optional_child("y").has_value());
  ASSERT_TRUE(reader.optional_child("x").has_value());
  EXPECT_EQ(reader.optional_child("x")->pointer(), "/x");
}

TEST(JsonReader, IntegersMayBeWrittenWithoutAFraction) {
  // JSON has one number type; JSON Schema's "integer" accepts 3.0 and so does the reader.
  const json doc = json::parse(R"({"a": 3, "b": 3.0, "c": 3e2, "d": 2.5, "e": "3", "f": 9223372036854775807,
                                  "g": 9223372036854775808, "h": 1e19, "i": -4})");
  const JsonReader reader(doc, "f.json");
  EXPECT_EQ(reader.integer_or("a", 0), 3);
  EXPECT_EQ(reader.integer_or("b", 0), 3);
  EXPECT_EQ(reader.integer_or("c", 0), 300);
  EXPECT_EQ(reader.integer_or("f", 0), std::numeric_limits<long long>::max());
  EXPECT_EQ(reader.integer_or("i", 0), -4);
  EXPECT_EQ(input_error_of([&] { reader.integer_or("d", 0, Interval::non_negative()); }),
            "f.json: /d: expected an integer >= 0, got number 2.5");
  EXPECT_THAT(input_error_of([&] { reader.integer_or("e", 0); }), HasSubstr("/e: expected an integer"));
  EXPECT_THAT(input_error_of([&] { reader.integer_or("g", 0); }), HasSubstr("/g: expected an integer"));
  EXPECT_THAT(input_error_of([&] { reader.integer_or("h", 0); }), HasSubstr("/h: expected an integer"));
}

TEST(JsonReader, Vec3NeedsThreeNumbersEachInRange) {
  const json doc = json::parse(R"({"a": [1, 2], "b": [1, "2", 3], "c": [1, -2, 3], "d": [0.5, 1, 2]})");
  const JsonReader reader(doc, "f.json", "/s");
  EXPECT_EQ(input_error_of([&] { reader.vec3("a"); }), "f.json: /s/a: expected an array of 3 numbers, got array [1,2]");
  EXPECT_THAT(input_error_of([&] { reader.vec3("b"); }), StartsWith("f.json: /s/b: expected an array of 3 numbers"));
  EXPECT_EQ(input_error_of([&] { reader.vec3("c", Interval::positive()); }),
            "f.json: /s/c: expected each component > 0, got -2 at index 1");
  EXPECT_EQ(reader.vec3("d", Interval::positive()), Eigen::Vector3d(0.5, 1.0, 2.0));
}

TEST(JsonReader, QuaternionIsStoredScalarLastAndMustBeUnit) {
  const double s = std::sqrt(0.5);
  const json doc = {{"q", {0.0, 0.0, s, s}}, {"long", {0, 0, 0, 2}}, {"short", {0, 0, 1}}};
  const JsonReader reader(doc, "f.json", "/b");
  const Eigen::Quaterniond q = reader.quaternion_or("q", Eigen::Quaterniond::Identity());
  EXPECT_DOUBLE_EQ(q.w(), s);
  EXPECT_DOUBLE_EQ(q.z(), s);
  EXPECT_EQ(q.x(), 0.0);
  EXPECT_EQ(q.y(), 0.0);
  EXPECT_EQ(input_error_of([&] { reader.quaternion_or("long", Eigen::Quaterniond::Identity()); }),
            "f.json: /b/long: expected a unit quaternion [qx, qy, qz, qw], got norm 2");
  EXPECT_THAT(input_error_of([&] { reader.quaternion_or("short", Eigen::Quaterniond::Identity()); }),
              StartsWith("f.json: /b/short: expected a quaternion [qx, qy, qz, qw] (4 numbers)"));
}

TEST(JsonReader, ChildrenAndElementsExtendThePointerWithEscapedTokens) {
  const json doc = json::parse(R"({"bodies": {"a/b": {"regions": [{}, {"min": 1}]}}})");
  const JsonReader body = JsonReader(doc, "f.json").child("bodies").members().front().second;
  EXPECT_EQ(body.pointer(), "/bodies/a~1b");
  const std::vector<JsonReader> regions = body.child("regions").elements();
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(input_error_of([&] { regions[1].vec3("min"); }),
            "f.json: /bodies/a~1b/regions/1/min: expected an array of 3 numbers, got number 1");
  EXPECT_THAT(input_error_of([&] { body.child("regions").members(); }),
              StartsWith("f.json: /bodies/a~1b/regions: expected an object"));
  EXPECT_THAT(input_error_of([&] { regions[0].elements(); }),
              StartsWith("f.json: /bodies/a~1b/regions/0: expected an array"));
}

TEST(JsonReader, LongValuesAreAbbreviatedInMessages) {
  const json doc = {{"x", std::string(100, 'a')}};
  const std::string message = input_error_of([&] { JsonReader(doc, "f").number("x"); });
  EXPECT_THAT(message, HasSubstr("..."));
  EXPECT_THAT(message, Not(HasSubstr(std::string(50, 'a'))));
}

// Describing a value serialised it whole before cutting the text: a value 100000 levels deep
// overflowed the stack, and one of millions of elements cost as much as its whole text.
TEST(DescribeJson, DeepAndHugeValuesAreDescribedBriefly) {
  json deep = json::array();
  json* inner = &deep;
  for (int level = 0; level < 100000; ++level) {
    inner->push_back(json::array());
    inner = &inner->back();
  }
  EXPECT_EQ(describe_json(deep), "array [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...");
  const json huge(std::vector<int>(1000000, 7));
  EXPECT_EQ(describe_json(huge), "array [7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,...");
  EXPECT_EQ(describe_json(json{{"a", {1, 2}}, {"b", "c"}}), "object {\"a\":[1,2],\"b\":\"c\"}");
  EXPECT_EQ(describe_json(json(std::string(1000000, 'x'))), "string \"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...");
}

}  // namespace
}  // namespace mssph
