#pragma once
// Typed access to JSON scene fields with errors that name the file and the field:
// "scene.json: shapes[2].radius: must be > 0 (got -1)". Every error is an InputError.

#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "materials/core/vec3.h"

namespace ochre {

class JsonFields {
 public:
  // `where` is "file: path.to.object".
  JsonFields(const nlohmann::json& object, std::string where);

  const nlohmann::json& json() const { return object_; }
  const std::string& where() const { return where_; }
  std::string child(const std::string& key) const;  // where of a member

  bool has(const char* key) const { return object_.contains(key); }
  const nlohmann::json& require(const char* key) const;
  // Rejects members not in `allowed` (typos must not be silently ignored).
  void check_known(std::initializer_list<const char*> allowed) const;

  double number(const char* key, double fallback, double min = -std::numeric_limits<double>::max(),
                double max = std::numeric_limits<double>::max(), bool min_exclusive = false) const;
  double required_number(const char* key, double min = -std::numeric_limits<double>::max(),
                         double max = std::numeric_limits<double>::max(), bool min_exclusive = false) const;
  long long integer(const char* key, long long fallback, long long min, long long max) const;
  std::string string(const char* key, const std::string& fallback) const;
  std::string required_string(const char* key) const;
  Vec3 vec3(const char* key, const Vec3& fallback) const;
  Vec3 required_vec3(const char* key) const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::json& object_;
  std::string where_;
};

// Parses a JSON value that must be an array of 3 finite numbers.
Vec3 json_vec3(const nlohmann::json& value, const std::string& where);

}  // namespace ochre
