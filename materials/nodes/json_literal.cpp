#include "materials/nodes/json_literal.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "materials/core/single_precision.h"

namespace ochre {

namespace {

float finite_number(const nlohmann::json& j, const char* what) {
  if (!j.is_number())
    throw std::invalid_argument(std::string(what) + " must be numbers, got " + json_excerpt(j));
  const double x = j.get<double>();
  if (!std::isfinite(static_cast<float>(x)))
    throw std::invalid_argument("NaN or infinite value " + json_excerpt(j) +
                                (std::isfinite(x) ? " (infinite in single precision)" : ""));
  if (const std::string problem = single_precision_problem(x); !problem.empty())
    throw std::invalid_argument("value " + json_excerpt(j) + " underflows (" + problem + ")");
  return static_cast<float>(x);
}

Vec3 three_numbers(const nlohmann::json& j, const char* what) {
  if (!j.is_array() || j.size() != 3)
    throw std::invalid_argument(std::string(what) + " must have exactly 3 numbers, got " + json_excerpt(j));
  return {finite_number(j[0], what), finite_number(j[1], what), finite_number(j[2], what)};
}

}  // namespace

std::optional<NodeValue> literal_value(const nlohmann::json& j) {
  if (j.is_number()) return NodeValue::of_float(finite_number(j, "a float"));
  if (j.is_array()) {
    const Vec3 c = three_numbers(j, "a colour [r, g, b]");
    return NodeValue::of_colour({c.x, c.y, c.z});
  }
  if (j.is_object() && j.contains("vector")) {
    if (j.size() != 1)
      throw std::invalid_argument("a vector is written {\"vector\": [x, y, z]} with no other key");
    return NodeValue::of_vector(three_numbers(j.at("vector"), "a vector"));
  }
  return std::nullopt;
}

std::string json_excerpt(const nlohmann::json& j) {
  std::string text = j.dump();
  constexpr size_t kMax = 60;
  if (text.size() > kMax) text = text.substr(0, kMax - 3) + "...";
  return text;
}

namespace {
template <class Number>
std::string shortest_text(Number x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof(text), x).ptr;
  return std::string(text, end);
}
}  // namespace

std::string number_text(double x) {
  return shortest_text(x);
}

std::string number_text(float x) {
  return shortest_text(x);
}

}  // namespace ochre
