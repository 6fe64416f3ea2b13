#include "renderer/json/json_fields.h"

#include <fmt/format.h>

#include <cmath>

#include "materials/core/single_precision.h"
#include "materials/nodes/json_literal.h"

namespace ochre {

namespace {

std::string join_where(const std::string& where, const std::string& key) {
  // "file.json: a.b" + "c" -> "file.json: a.b.c"; "file.json:" + "c" -> "file.json: c"
  if (!where.empty() && where.back() == ':') return where + " " + key;
  return where + "." + key;
}

[[noreturn]] void fail_at(const std::string& where, const std::string& message) {
  throw InputError(fmt::format("{}: {}", where, message));
}

// "must be > 0", "must be in [0, 179]", "must be a finite number".
std::string range_text(double min, double max, bool min_exclusive) {
  const bool has_min = min > kNoMinimum, has_max = max < kNoMaximum;
  if (has_min && has_max) return fmt::format("must be in {}{}, {}]", min_exclusive ? "(" : "[", min, max);
  if (has_min) return fmt::format("must be {} {}", min_exclusive ? ">" : ">=", min);
  if (has_max) return fmt::format("must be <= {}", max);
  return "must be a finite number";
}

}  // namespace

double json_number(const nlohmann::json& v, const std::string& where, double min, double max,
                   bool min_exclusive) {
  if (!v.is_number()) fail_at(where, fmt::format("expected a number, got {}", json_excerpt(v)));
  const double x = v.get<double>();
  const std::string range = range_text(min, max, min_exclusive);
  if (const std::string problem = single_precision_problem(x); !problem.empty())
    fail_at(where, fmt::format("{} (got {}, {})", range, json_excerpt(v), problem));
  if (min_exclusive ? !(x > min) : !(x >= min))
    fail_at(where, fmt::format("{} (got {})", range, json_excerpt(v)));
  if (!(x <= max)) fail_at(where, fmt::format("{} (got {})", range, json_excerpt(v)));
  return x;
}

long long json_integer(const nlohmann::json& v, const std::string& where, long long min, long long max) {
  if (!v.is_number()) fail_at(where, fmt::format("expected an integer, got {}", json_excerpt(v)));
  const std::string range = fmt::format("must be an integer in [{}, {}]", min, max);
  // Compared in the JSON number's own type: a conversion first could wrap (4294967297 -> 1, -1 -> 2^64-1).
  if (v.is_number_unsigned()) {
    const auto u = v.get<unsigned long long>();
    if (max < 0 || u > static_cast<unsigned long long>(max) || static_cast<long long>(u) < min)
      fail_at(where, fmt::format("{} (got {})", range, json_excerpt(v)));
    return static_cast<long long>(u);
  }
  if (v.is_number_integer()) {
    const auto i = v.get<long long>();
    if (i < min || i > max) fail_at(where, fmt::format("{} (got {})", range, json_excerpt(v)));
    return i;
  }
  const double x = v.get<double>();
  if (!(x == std::floor(x))) fail_at(where, fmt::format("expected an integer, got {}", json_excerpt(v)));
  // 2^63 bounds the conversion: static_cast<double>(LLONG_MAX) rounds up to it.
  if (!(x >= static_cast<double>(min) && x <= static_cast<double>(max) && x < 0x1p63 && x >= -0x1p63))
    fail_at(where, fmt::format("{} (got {})", range, json_excerpt(v)));
  return static_cast<long long>(x);
}

bool json_boolean(const nlohmann::json& v, const std::string& where) {
  if (!v.is_boolean()) fail_at(where, fmt::format("expected true or false, got {}", json_excerpt(v)));
  return v.get<bool>();
}

std::string json_string(const nlohmann::json& v, const std::string& where) {
  if (!v.is_string()) fail_at(where, fmt::format("expected a string, got {}", json_excerpt(v)));
  return v.get<std::string>();
}

const nlohmann::json& json_array(const nlohmann::json& v, const std::string& where, size_t size,
                                 const char* shape) {
  if (!v.is_array() || v.size() != size)
    fail_at(where, fmt::format("expected {}, got {}", shape, json_excerpt(v)));
  return v;
}

Vec3d json_vec3d(const nlohmann::json& v, const std::string& where) {
  json_array(v, where, 3, "an array of 3 numbers [x, y, z]");
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = json_number(v[i], fmt::format("{}[{}]", where, i));
  return {r[0], r[1], r[2]};
}

Vec3 json_vec3(const nlohmann::json& v, const std::string& where) {
  return json_vec3d(v, where).to_float();
}

JsonFields::JsonFields(const nlohmann::json& object, std::string where)
    : object_(object), where_(std::move(where)) {
  if (!object_.is_object()) throw InputError(fmt::format("{}: expected a JSON object", where_));
}

std::string JsonFields::child(const std::string& key) const {
  return join_where(where_, key);
}

void JsonFields::fail(const std::string& key, const std::string& message) const {
  fail_at(key.empty() ? where_ : child(key), message);
}

void JsonFields::rethrow_in_context(const std::string& key, const std::string& message) const {
  if (message.find(where_) != std::string::npos) throw InputError(message);
  fail(key, message);
}

const nlohmann::json& JsonFields::require(const char* key) const {
  const auto it = object_.find(key);
  if (it == object_.end()) fail(key, "missing required parameter");
  return *it;
}

void JsonFields::check_known(std::initializer_list<const char*> allowed) const {
  for (const auto& [key, value] : object_.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(key, fmt::format("unknown parameter '{}' (known: {})", key, list));
  }
}

double JsonFields::required_number(const char* key, double min, double max, bool min_exclusive) const {
  return json_number(require(key), child(key), min, max, min_exclusive);
}

double JsonFields::number(const char* key, double fallback, double min, double max,
                          bool min_exclusive) const {
  return has(key) ? required_number(key, min, max, min_exclusive) : fallback;
}

long long JsonFields::integer(const char* key, long long fallback, long long min, long long max) const {
  return has(key) ? json_integer(require(key), child(key), min, max) : fallback;
}

bool JsonFields::boolean(const char* key, bool fallback) const {
  return has(key) ? json_boolean(require(key), child(key)) : fallback;
}

std::string JsonFields::required_string(const char* key) const {
  return json_string(require(key), child(key));
}

std::string JsonFields::string(const char* key, const std::string& fallback) const {
  return has(key) ? required_string(key) : fallback;
}

Vec3 JsonFields::required_vec3(const char* key) const {
  return json_vec3(require(key), child(key));
}

Vec3 JsonFields::vec3(const char* key, const Vec3& fallback) const {
  return has(key) ? required_vec3(key) : fallback;
}

Vec3d JsonFields::required_vec3d(const char* key) const {
  return json_vec3d(require(key), child(key));
}

Vec3d JsonFields::vec3d(const char* key, const Vec3d& fallback) const {
  return has(key) ? required_vec3d(key) : fallback;
}

}  // namespace ochre
