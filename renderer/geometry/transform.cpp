#include "renderer/geometry/transform.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "materials/nodes/json_literal.h"
#include "renderer/json/json_fields.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

// The 3x3 cofactor matrix of the linear part: cof = det * inverse-transpose (row-major, 9 entries).
std::array<double, 9> cofactors3(const Transform& t) {
  auto a = [&](int r, int c) { return t(r, c); };
  return {a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1), a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2),
          a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0), a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2),
          a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0), a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1),
          a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1), a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2),
          a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0)};
}

double determinant_from(const Transform& t, const std::array<double, 9>& cof) {
  return t(0, 0) * cof[0] + t(0, 1) * cof[1] + t(0, 2) * cof[2];
}

// cos and sin of an angle in degrees, exact at multiples of 90 degrees so that axis-aligned
// rotations produce exact 0 and +-1 entries.
void cos_sin_degrees(double degrees, double& c, double& s) {
  const double quarter_turns = degrees / 90.0;
  if (quarter_turns == std::round(quarter_turns)) {
    const long k = static_cast<long>(std::fmod(std::round(quarter_turns), 4.0) + 4) % 4;
    static constexpr double kCos[4] = {1, 0, -1, 0}, kSin[4] = {0, 1, 0, -1};
    c = kCos[k];
    s = kSin[k];
    return;
  }
  const double radians = degrees * (M_PI / 180.0);
  c = std::cos(radians);
  s = std::sin(radians);
}

}  // namespace

Transform Transform::translate(Vec3d offset) {
  Transform t;
  t(0, 3) = offset.x;
  t(1, 3) = offset.y;
  t(2, 3) = offset.z;
  return t;
}

Transform Transform::scale(Vec3d factors) {
  Transform t;
  t(0, 0) = factors.x;
  t(1, 1) = factors.y;
  t(2, 2) = factors.z;
  return t;
}

// Rodrigues' rotation formula: R = cos I + sin [k]x + (1 - cos) k k^T.
Transform Transform::rotate(double degrees, Vec3 axis) {
  const double len = std::sqrt(double(axis.x) * axis.x + double(axis.y) * axis.y + double(axis.z) * axis.z);
  if (!(len > 0.0) || !std::isfinite(len))
    throw std::invalid_argument("Transform::rotate: zero or non-finite axis");
  const double k[3] = {axis.x / len, axis.y / len, axis.z / len};
  double c, s;
  cos_sin_degrees(degrees, c, s);
  const double cross_matrix[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
  Transform t;
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col)
      t(r, col) = (r == col ? c : 0.0) + s * cross_matrix[r][col] + (1 - c) * k[r] * k[col];
  return t;
}

Transform Transform::look_at(Vec3d eye, Vec3d target, Vec3d up) {
  const Vec3d view = target - eye;
  if (!(length(view) > 0.0)) throw std::invalid_argument("Transform::look_at: eye and target coincide");
  const Vec3d forward = view * (1.0 / length(view));
  const Vec3d side = cross(forward, up);
  if (!(length(side) > 1e-6 * length(up))) {
    throw std::invalid_argument("Transform::look_at: up is zero or parallel to the view direction");
  }
  const Vec3d right = side * (1.0 / length(side));
  const Vec3d true_up = cross(right, forward);
  Transform t;
  const Vec3d columns[4] = {right, true_up, forward, eye};
  for (int col = 0; col < 4; ++col)
    for (int r = 0; r < 3; ++r)
      t(r, col) = r == 0 ? columns[col].x : r == 1 ? columns[col].y : columns[col].z;
  return t;
}

Transform Transform::operator*(const Transform& o) const {
  Transform out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += (*this)(r, k) * o(k, c);
      out(r, c) = sum;
    }
  return out;
}

// Affine inverse: [L t]^-1 = [L^-1, -L^-1 t], with L^-1 = cofactors^T / det (in double).
Transform Transform::inverse() const {
  const auto cof = cofactors3(*this);
  const double det = determinant_from(*this, cof);
  if (det == 0.0 || !std::isfinite(det)) throw std::invalid_argument("Transform::inverse: singular matrix");
  double inv[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) inv[r][c] = cof[3 * c + r] / det;
  Transform out;
  for (int r = 0; r < 3; ++r) {
    double translation = 0;
    for (int c = 0; c < 3; ++c) {
      out(r, c) = inv[r][c];
      translation -= inv[r][c] * (*this)(c, 3);
    }
    out(r, 3) = translation;
  }
  return out;
}

Vec3d Transform::point_double(const Vec3d& p) const {
  return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
          m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}

Vec3 Transform::point(Vec3 p) const {
  return point_double(Vec3d(p)).to_float();
}

Vec3 Transform::vector(Vec3 v) const {
  const double x = v.x, y = v.y, z = v.z;
  return Vec3d{m[0] * x + m[1] * y + m[2] * z, m[4] * x + m[5] * y + m[6] * z,
               m[8] * x + m[9] * y + m[10] * z}
      .to_float();
}

// The cofactor matrix is det * L^-T; its sign is corrected by sign(det), its scale by normalize.
Vec3 Transform::normal(Vec3 n) const {
  const auto cof = cofactors3(*this);
  const double sign = determinant_from(*this, cof) < 0 ? -1.0 : 1.0;
  const Vec3 out{static_cast<float>(sign * (cof[0] * n.x + cof[1] * n.y + cof[2] * n.z)),
                 static_cast<float>(sign * (cof[3] * n.x + cof[4] * n.y + cof[5] * n.z)),
                 static_cast<float>(sign * (cof[6] * n.x + cof[7] * n.y + cof[8] * n.z))};
  return normalize(out);
}

float Transform::determinant3() const {
  return static_cast<float>(determinant_from(*this, cofactors3(*this)));
}

// ------------------------------------------------------------------------------------- parsing

namespace {

[[noreturn]] void fail_with_value(const std::string& where, const std::string& what,
                                  const nlohmann::json& value) {
  throw InputError(fmt::format("{}: {}, got {}", where, what, json_excerpt(value)));
}

double parse_finite(const nlohmann::json& value, const std::string& where) {
  return json_number(value, where);
}

Transform parse_matrix(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 16)
    fail_with_value(where, "expected an array of 16 numbers (row-major 4x4 matrix)", value);
  Transform t;
  for (int i = 0; i < 16; ++i) t.m[i] = parse_finite(value[i], fmt::format("{}[{}]", where, i));
  if (t.m[12] != 0 || t.m[13] != 0 || t.m[14] != 0 || t.m[15] != 1) {
    fail_with_value(where, "the bottom row of an affine matrix must be [0, 0, 0, 1]", value);
  }
  return t;
}

const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) fail_with_value(where, fmt::format("missing \"{}\"", key), object);
  return *it;
}

Transform parse_rotate(const nlohmann::json& value, const std::string& where) {
  if (!value.is_object()) fail_with_value(where, "expected {\"axis\": [x, y, z], \"angle\": degrees}", value);
  for (const auto& [key, unused] : value.items()) {
    if (key != "axis" && key != "angle")
      fail_with_value(where, fmt::format("unknown key \"{}\"", key), value);
  }
  const Vec3 axis = json_vec3(member(value, "axis", where), where + ".axis");
  // The length is squared on the way: [1e-30, 0, 0] is zero and [1e30, 0, 0] infinite in single precision.
  if (!(length(axis) > 0.0f) || !std::isfinite(length(axis)))
    fail_with_value(where + ".axis", "the rotation axis must be non-zero with a finite length",
                    value["axis"]);
  return Transform::rotate(parse_finite(member(value, "angle", where), where + ".angle"), axis);
}

Transform parse_look_at(const nlohmann::json& value, const std::string& where) {
  if (!value.is_object())
    fail_with_value(where, "expected {\"eye\": [..], \"target\": [..], \"up\": [..]}", value);
  for (const auto& [key, unused] : value.items()) {
    if (key != "eye" && key != "target" && key != "up")
      fail_with_value(where, fmt::format("unknown key \"{}\"", key), value);
  }
  const Vec3d eye = json_vec3d(member(value, "eye", where), where + ".eye");
  const Vec3d target = json_vec3d(member(value, "target", where), where + ".target");
  const Vec3d up = json_vec3d(member(value, "up", where), where + ".up");
  try {
    return Transform::look_at(eye, target, up);
  } catch (const std::invalid_argument& e) {
    fail_with_value(where, e.what(), value);
  }
}

Transform parse_scale(const nlohmann::json& value, const std::string& where) {
  const double s = value.is_number() ? parse_finite(value, where) : 0.0;
  const Vec3d factors = value.is_number() ? Vec3d(s, s, s) : json_vec3d(value, where);
  if (factors.x == 0 || factors.y == 0 || factors.z == 0)
    fail_with_value(where, "scale factors must not be zero", value);
  return Transform::scale(factors);
}

Transform parse_operation(const nlohmann::json& op, const std::string& where) {
  if (!op.is_object() || op.size() != 1) {
    fail_with_value(where, "expected an object with one key: translate, scale, rotate, matrix or look_at",
                    op);
  }
  const std::string key = op.begin().key();
  const nlohmann::json& value = op.begin().value();
  const std::string at = where + "." + key;
  if (key == "translate") return Transform::translate(json_vec3d(value, at));
  if (key == "scale") return parse_scale(value, at);
  if (key == "rotate") return parse_rotate(value, at);
  if (key == "matrix") return parse_matrix(value, at);
  if (key == "look_at") return parse_look_at(value, at);
  fail_with_value(
      where,
      fmt::format("unknown operation \"{}\" (expected translate, scale, rotate, matrix or look_at)", key),
      op);
}

}  // namespace

Transform parse_transform(const nlohmann::json& value, const std::string& where) {
  Transform result;
  if (value.is_object()) {
    result = parse_operation(value, where);
  } else if (value.is_array() && value.size() == 16 && value[0].is_number()) {
    result = parse_matrix(value, where);
  } else if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i) {
      result = parse_operation(value[i], fmt::format("{}[{}]", where, i)) * result;
    }
  } else {
    fail_with_value(where, "expected a 16-number matrix, an operation object or an array of operations",
                    value);
  }
  const float det = result.determinant3();
  if (!(std::fabs(det) > 0.0f) || !std::isfinite(det))
    fail_with_value(where, "the transform is singular (or its scale over- or underflows single precision)",
                    value);
  return result;
}

}  // namespace ochre
