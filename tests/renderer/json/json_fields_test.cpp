// The typed readers of scene JSON (renderer/json/json_fields.h) and the duplicate-key check of the JSON
// reader (renderer/json/json_duplicate_keys.h): wrong types, fractional, wrapping and out-of-range integers,
// numbers outside single precision and repeated keys are InputErrors naming the field.
#include "renderer/json/json_fields.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "renderer/json/json_duplicate_keys.h"
#include "spectra/input_error.h"
#include "support/input_error_of.h"

namespace ochre::json_fields_test {
namespace {

using nlohmann::json;

using test::input_error_of;

TEST(JsonInteger, AcceptsIntegralNumbersInRange) {
  EXPECT_EQ(json_integer(json::parse("8"), "f", 1, 10), 8);
  EXPECT_EQ(json_integer(json::parse("8.0"), "f", 1, 10), 8);
  EXPECT_EQ(json_integer(json::parse("-3"), "f", -5, 0), -3);
  EXPECT_EQ(json_integer(json::parse("9223372036854775807"), "f", 0, std::numeric_limits<long long>::max()),
            std::numeric_limits<long long>::max());
}

TEST(JsonInteger, RejectsFractionsWrongTypesAndValuesThatWouldWrap) {
  EXPECT_EQ(input_error_of([] { json_integer(json::parse("2.5"), "s.json: integrator.spp", 1, 10); }),
            "s.json: integrator.spp: expected an integer, got 2.5");
  EXPECT_EQ(
      input_error_of([] { json_integer(json::parse("4294967297"), "s.json: integrator.spp", 1, 16777216); }),
      "s.json: integrator.spp: must be an integer in [1, 16777216] (got 4294967297)");
  EXPECT_NE(input_error_of([] { json_integer(json::parse("18446744073709551615"), "f", -1, 10); }), "");
  EXPECT_NE(input_error_of([] {
              json_integer(json::parse("9223372036854775808"), "f", 0, std::numeric_limits<long long>::max());
            }),
            "");
  EXPECT_NE(input_error_of(
                [] { json_integer(json::parse("9.3e18"), "f", 0, std::numeric_limits<long long>::max()); }),
            "");
  EXPECT_NE(input_error_of([] { json_integer(json::parse("1e300"), "f", 0, 1024); }), "");
  EXPECT_NE(input_error_of([] { json_integer(json::parse("-1"), "f", 0, 10); }), "");
  EXPECT_NE(input_error_of([] { json_integer(json::parse("true"), "f", 0, 10); }), "");
  EXPECT_NE(input_error_of([] { json_integer(json::parse("\"3\""), "f", 0, 10); }), "");
}

TEST(JsonNumber, RejectsValuesOutsideSinglePrecision) {
  EXPECT_EQ(
      input_error_of([] { json_number(json::parse("1e-50"), "s.json: shapes[0].radius", 0.0, 1e30, true); }),
      "s.json: shapes[0].radius: must be in (0, 1e+30] (got 1e-50, which is 0 in single precision)");
  EXPECT_NE(
      input_error_of([] { json_number(json::parse("1e39"), "f"); }).find("infinite in single precision"),
      std::string::npos);
  EXPECT_NE(input_error_of([] { json_number(json::parse("-1e-40"), "f"); }).find("smallest normal"),
            std::string::npos);
  EXPECT_EQ(json_number(json::parse("0"), "f"), 0.0);
  EXPECT_EQ(json_number(json::parse("3.4e38"), "f"), 3.4e38);
  EXPECT_EQ(json_number(json::parse("1.2e-38"), "f"), 1.2e-38);
}

TEST(JsonBoolean, AcceptsOnlyTrueAndFalse) {
  EXPECT_TRUE(json_boolean(json::parse("true"), "f"));
  EXPECT_FALSE(json_boolean(json::parse("false"), "f"));
  for (const char* text : {"\"yes\"", "1", "0", "null", "[true]"})
    EXPECT_NE(input_error_of([&] {
                json_boolean(json::parse(text), "s.json: output.aovs");
              }).find("s.json: output.aovs: expected true or false"),
              std::string::npos)
        << text;
  const json object = json::parse(R"({"stokes": "yes"})");
  const JsonFields fields(object, "s.json: output");
  EXPECT_EQ(input_error_of([&] { fields.boolean("stokes", false); }),
            "s.json: output.stokes: expected true or false, got \"yes\"");
  EXPECT_TRUE(fields.boolean("aovs", true));  // absent: the fallback
}

TEST(JsonFieldsContext, NamesTheFieldOfAnErrorFromCodeThatDoesNotKnowTheScene) {
  const json object = json::parse(R"({"radius": 1})");
  const JsonFields fields(object, "s.json: shapes[2]");
  EXPECT_EQ(
      input_error_of([&] { fields.in_context("", [] { throw InputError("sphere: radius must be > 0"); }); }),
      "s.json: shapes[2]: sphere: radius must be > 0");
  EXPECT_EQ(input_error_of([&] {
              fields.in_context("transform", [] { throw std::invalid_argument("singular matrix"); });
            }),
            "s.json: shapes[2].transform: singular matrix");
  // A message that names the shape already is kept as it is.
  EXPECT_EQ(input_error_of([&] {
              fields.in_context("file", [] { throw InputError("s.json: shapes[2]: no triangles"); });
            }),
            "s.json: shapes[2]: no triangles");
  EXPECT_EQ(fields.in_context("", [] { return 7; }), 7);
}

TEST(JsonDuplicateKeys, NamesThePathAndTheKey) {
  EXPECT_EQ(input_error_of([] { parse_json_rejecting_duplicate_keys(R"({"a": 1, "a": 2})", "s.json"); }),
            "s.json: a: duplicate key \"a\" (a key may appear once per object)");
  EXPECT_EQ(input_error_of([] {
              parse_json_rejecting_duplicate_keys(
                  R"({"shapes": [{"type": "x"}, [1, [2]], {"r": 1, "r": 1}]})", "s.json");
            }),
            "s.json: shapes[2].r: duplicate key \"r\" (a key may appear once per object)");
  EXPECT_EQ(input_error_of([] {
              parse_json_rejecting_duplicate_keys(
                  R"({"m": {"nodes": {"a": {"x": 1}, "b": {"x": 1, "y": {"z": 1, "z": 2}}}}})", "s.json");
            }),
            "s.json: m.nodes.b.y.z: duplicate key \"z\" (a key may appear once per object)");
}

TEST(JsonDuplicateKeys, EqualKeysInDifferentObjectsAndCommentsAreFine) {
  const json j = parse_json_rejecting_duplicate_keys(
      R"({"shapes": [{"type": "a", "r": [1, 2]}, {"type": "b"}], /* note */ "lights": [[{"type": "c"}]], "type": 1})",
      "s.json");
  EXPECT_EQ(j["shapes"][1]["type"], "b");
  EXPECT_EQ(j["lights"][0][0]["type"], "c");
  EXPECT_EQ(j["type"], 1);
  EXPECT_THROW(parse_json_rejecting_duplicate_keys("{\"a\": }", "s.json"), json::parse_error);
}

}  // namespace
}  // namespace ochre::json_fields_test
