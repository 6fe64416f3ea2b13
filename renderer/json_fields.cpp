#include "renderer/json_fields.h"

#include <fmt/format.h>

#include <cmath>

#include "renderer/input_error.h"

namespace ochre {

namespace {
std::string join_where(const std::string& where, const std::string& key) {
  // "file.json: a.b" + "c" -> "file.json: a.b.c"; "file.json:" + "c" -> "file.json: c"
  if (!where.empty() && where.back() == ':') return where + " " + key;
  return where + "." + key;
}
}  // namespace

JsonFields::JsonFields(const nlohmann::json& object, std::string where)
    : object_(object), where_(std::move(where)) {
  if (!object_.is_object()) throw InputError(fmt::format("{}: expected a JSON object", where_));
}

std::string JsonFields::child(const std::string& key) const {
  return join_where(where_, key);
}

void JsonFields::fail(const std::string& key, const std::string& message) const {
  throw InputError(fmt::format("{}: {}", key.empty() ? where_ : child(key), message));
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
  const nlohmann::json& v = require(key);
  if (!v.is_number()) fail(key, fmt::format("expected a number, got {}", v.dump()));
  const double x = v.get<double>();
  // Scene numbers become floats: anything beyond float range would be +-Inf.
  if (!std::isfinite(x) || std::fabs(x) > 3.0e38) fail(key, fmt::format("must be finite (got {})", v.dump()));
  if (min_exclusive ? !(x > min) : !(x >= min))
    fail(key, fmt::format("must be {} {} (got {})", min_exclusive ? ">" : ">=", min, x));
  if (!(x <= max)) fail(key, fmt::format("must be <= {} (got {})", max, x));
  return x;
}

double JsonFields::number(const char* key, double fallback, double min, double max,
                          bool min_exclusive) const {
  return has(key) ? required_number(key, min, max, min_exclusive) : fallback;
}

long long JsonFields::integer(const char* key, long long fallback, long long min, long long max) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = require(key);
  if (!v.is_number_integer()) fail(key, fmt::format("expected an integer, got {}", v.dump()));
  const long long x = v.get<long long>();
  if (x < min || x > max) fail(key, fmt::format("must be in [{}, {}] (got {})", min, max, x));
  return x;
}

std::string JsonFields::required_string(const char* key) const {
  const nlohmann::json& v = require(key);
  if (!v.is_string()) fail(key, fmt::format("expected a string, got {}", v.dump()));
  return v.get<std::string>();
}

std::string JsonFields::string(const char* key, const std::string& fallback) const {
  return has(key) ? required_string(key) : fallback;
}

Vec3 json_vec3(const nlohmann::json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 3)
    throw InputError(fmt::format("{}: expected [x, y, z], got {}", where, v.dump()));
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) || std::fabs(v[i].get<double>()) > 3.0e38)
      throw InputError(fmt::format("{}: expected 3 finite numbers, got {}", where, v.dump()));
    r[i] = v[i].get<float>();
  }
  return r;
}

Vec3 JsonFields::required_vec3(const char* key) const {
  return json_vec3(require(key), child(key));
}
Vec3 JsonFields::vec3(const char* key, const Vec3& fallback) const {
  return has(key) ? required_vec3(key) : fallback;
}

}  // namespace ochre
