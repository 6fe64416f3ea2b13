#include "renderer/geometry/transform.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "renderer/json/json_fields.h"
#include "spectra/input_error.h"

namespace ochre::transform_test {
namespace {

void expect_near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// The InputError message of parsing `text` (empty when it parses).
std::string parse_error(const std::string& text) {
  try {
    parse_transform(nlohmann::json::parse(text), "scene.json: shapes[2].transform");
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Transform, ComposeAppliesRightOperandFirst) {
  const Transform t = Transform::scale({2, 3, 4}) * Transform::translate({1, 1, 1});
  expect_near(t.point({0, 0, 0}), {2, 3, 4});
  expect_near(t.point({1, 0, -1}), {4, 3, 0});
  // Vectors ignore the translation.
  expect_near(t.vector({1, 1, 1}), {2, 3, 4});
}

TEST(Transform, RotationsByQuarterTurnsAreExact) {
  const Transform r = Transform::rotate(90, {0, 0, 1});
  EXPECT_EQ(r.point({1, 0, 0}), Vec3(0, 1, 0));  // counter-clockwise about +z
  EXPECT_EQ(Transform::rotate(-90, {1, 0, 0}).point({0, 0, 1}), Vec3(0, 1, 0));
  EXPECT_EQ(Transform::rotate(180, {0, 1, 0}).point({1, 2, 3}), Vec3(-1, 2, -3));
  // A general rotation keeps lengths and the axis.
  const Transform g = Transform::rotate(37, {1, 2, 3});
  expect_near(g.point({1, 2, 3}), {1, 2, 3});
  EXPECT_NEAR(length(g.point({-2, 0.5f, 4})), length(Vec3(-2, 0.5f, 4)), 1e-5f);
  EXPECT_NEAR(g.determinant3(), 1.0f, 1e-6f);
}

TEST(Transform, InverseUndoesAffineTransforms) {
  const Transform t = Transform::translate({3, -2, 7}) * Transform::rotate(33, {1, -1, 0.5f}) *
                      Transform::scale({0.5f, 2, -3});
  const Transform identity = t * t.inverse();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(identity(r, c), r == c ? 1.0f : 0.0f, 1e-5f);
  const Vec3 p{0.3f, -4, 9};
  expect_near(t.inverse().point(t.point(p)), p, 1e-4f);
  EXPECT_THROW(Transform::scale({1, 0, 1}).inverse(), std::invalid_argument);
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  // The plane z = x has normal (-1, 0, 1)/sqrt2; scaling x by 2 gives z = x/2, normal (-1, 0, 2)/sqrt5.
  const Transform s = Transform::scale({2, 1, 1});
  expect_near(s.normal(normalize(Vec3(-1, 0, 1))), normalize(Vec3(-1, 0, 2)));
  // And in general the transformed normal is perpendicular to transformed tangents, and unit.
  const Transform t = Transform::rotate(20, {0, 1, 1}) * Transform::scale({3, 0.2f, 1.5f});
  const Vec3 tangent1{1, 2, 0}, tangent2{0, 1, -1};
  const Vec3 n = t.normal(cross(tangent1, tangent2));
  EXPECT_NEAR(length(n), 1.0f, 1e-6f);
  EXPECT_NEAR(dot(n, normalize(t.vector(tangent1))), 0.0f, 1e-5f);
  EXPECT_NEAR(dot(n, normalize(t.vector(tangent2))), 0.0f, 1e-5f);
  // A mirror keeps the normal on the side the mirrored surface faces.
  expect_near(Transform::scale({1, 1, -1}).normal({0, 0, 1}), {0, 0, -1});
}

TEST(Transform, HandednessFlipsWithMirrorsOnly) {
  EXPECT_FALSE(Transform::rotate(75, {1, 1, 0}).flips_handedness());
  EXPECT_FALSE(Transform::scale({-1, -1, 1}).flips_handedness());
  EXPECT_TRUE(Transform::scale({-1, 1, 1}).flips_handedness());
}

TEST(Transform, LookAtMapsCameraAxes) {
  const Vec3 eye{1, 2, 3}, target{1, 2, -7};
  const Transform c = Transform::look_at(Vec3d(eye), Vec3d(target), {0, 1, 0});
  expect_near(c.point({0, 0, 0}), eye);
  expect_near(c.vector({0, 0, 1}), {0, 0, -1});  // looks along camera +z
  expect_near(c.vector({0, 1, 0}), {0, 1, 0});   // +y up
  expect_near(c.vector({1, 0, 0}), {1, 0, 0});   // +x right (looking down -z with y up)
  EXPECT_TRUE(c.flips_handedness());
  // A tilted up vector is re-orthogonalized.
  const Transform tilted = Transform::look_at({0, 0, 0}, {0, 0, 5}, {0, 1, 1});
  expect_near(tilted.vector({0, 1, 0}), {0, 1, 0});
  EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 0, 1}, {0, 0, 2}), std::invalid_argument);
}

TEST(TransformParse, MatrixAndOperationsInOrder) {
  const Transform m = parse_transform(nlohmann::json::parse("[1,0,0,5, 0,2,0,0, 0,0,1,0, 0,0,0,1]"), "t");
  expect_near(m.point({1, 1, 1}), {6, 2, 1});
  // Translate first, then scale: the translation is scaled too.
  const Transform ops =
      parse_transform(nlohmann::json::parse(R"([{"translate": [1, 0, 0]}, {"scale": 2}])"), "t");
  expect_near(ops.point({0, 0, 0}), {2, 0, 0});
  const Transform rot = parse_transform(
      nlohmann::json::parse(R"([{"rotate": {"axis": [0, 0, 2], "angle": 90}}, {"scale": [1, 3, 1]}])"), "t");
  expect_near(rot.point({1, 0, 0}), {0, 3, 0});
  const Transform single = parse_transform(nlohmann::json::parse(R"({"translate": [0, 0, -1]})"), "t");
  expect_near(single.point({0, 0, 0}), {0, 0, -1});
  const Transform look = parse_transform(
      nlohmann::json::parse(R"([{"look_at": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0]}}])"),
      "t");
  expect_near(look.vector({0, 0, 1}), {0, 0, -1});
  EXPECT_EQ(parse_transform(nlohmann::json::array(), "t").m, Transform::identity().m);
}

TEST(TransformParse, ErrorsNameThePosition) {
  const std::string prefix = "scene.json: shapes[2].transform";
  EXPECT_NE(parse_error(R"([{"translate": [0, 0, 0]}, {"rotate": {"axis": [0, 0, 0], "angle": 3}}])")
                .find(prefix + "[1].rotate.axis"),
            std::string::npos);
  EXPECT_NE(parse_error(R"([{"translate": [0, "x", 0]}])").find(prefix + "[0].translate[1]"),
            std::string::npos);
  EXPECT_NE(parse_error(R"([{"translate": [0, 0]}])").find(prefix + "[0].translate: expected an array of 3"),
            std::string::npos);
  EXPECT_NE(parse_error(R"([{"spin": 3}])").find("unknown operation \"spin\""), std::string::npos);
  EXPECT_NE(parse_error(R"([{"scale": 2, "translate": [1, 1, 1]}])").find(prefix + "[0]"), std::string::npos);
  EXPECT_NE(parse_error(R"([{"scale": [1, 0, 1]}])").find("must not be zero"), std::string::npos);
  EXPECT_NE(parse_error(R"([{"rotate": {"axis": [0, 0, 1]}}])").find("missing \"angle\""), std::string::npos);
  EXPECT_NE(parse_error(R"([{"rotate": {"axis": [0, 0, 1], "angel": 3, "angle": 1}}])")
                .find("unknown key \"angel\""),
            std::string::npos);
  EXPECT_NE(parse_error("[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]").find("bottom row"), std::string::npos);
  EXPECT_NE(parse_error("[1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]").find("singular"), std::string::npos);
  EXPECT_NE(parse_error(R"("rotate")").find(prefix + ": expected"), std::string::npos);
  EXPECT_NE(parse_error(R"([{"look_at": {"eye": [0, 0, 1], "target": [0, 0, 1], "up": [0, 1, 0]}}])")
                .find(prefix + "[0].look_at"),
            std::string::npos);
}

TEST(JsonVec3, RejectsNonFiniteAndWrongShapes) {
  expect_near(json_vec3(nlohmann::json::parse("[1, -2.5, 3e2]"), "v"), {1, -2.5f, 300});
  EXPECT_THROW(json_vec3(nlohmann::json::parse("[1, 2]"), "v"), InputError);
  EXPECT_THROW(json_vec3(nlohmann::json::parse("[1, 2, 1e39]"), "v"), InputError);  // overflows float
  EXPECT_THROW(json_vec3(nlohmann::json::parse("{\"x\": 1}"), "v"), InputError);
  try {
    json_vec3(nlohmann::json::parse("[1, null, 3]"), "materials[0].colour");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials[0].colour[1]: expected a number, got null"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ochre::transform_test
