#pragma once
// Typed access to JSON scene fields with errors that name the file and the field:
// "scene.json: shapes[2].radius: must be > 0 (got -1)". Every error is an InputError. Every read of
// scene JSON goes through these checks (docs/scene-format.md, "Validation"):
//   numbers   finite, representable in single precision (neither infinite nor below the smallest normal
//             float once converted), in range;
//   integers  integral (8 and 8.0 are the same JSON number, 8.5 is not an integer), range-checked before
//             any conversion so nothing wraps;
//   booleans  true or false only (not "yes", 1 or null).

#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#include "materials/core/vec3.h"
#include "materials/core/vec3d.h"
#include "spectra/input_error.h"

namespace ochre {

inline constexpr double kNoMinimum = -std::numeric_limits<double>::max();
inline constexpr double kNoMaximum = std::numeric_limits<double>::max();

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

  double number(const char* key, double fallback, double min = kNoMinimum, double max = kNoMaximum,
                bool min_exclusive = false) const;
  double required_number(const char* key, double min = kNoMinimum, double max = kNoMaximum,
                         bool min_exclusive = false) const;
  long long integer(const char* key, long long fallback, long long min, long long max) const;
  bool boolean(const char* key, bool fallback) const;
  std::string string(const char* key, const std::string& fallback) const;
  std::string required_string(const char* key) const;
  Vec3 vec3(const char* key, const Vec3& fallback) const;
  Vec3 required_vec3(const char* key) const;
  // Positions: the same checks, the numbers kept in double precision (renderer/scene/scene.h, origin).
  Vec3d vec3d(const char* key, const Vec3d& fallback) const;
  Vec3d required_vec3d(const char* key) const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  // Runs `build` (geometry, lights, file imports: code that does not know the scene) and turns an
  // InputError or std::invalid_argument it throws into an InputError naming this object's `key` ("" for
  // the object itself), unless the message names this object already.
  template <class Build>
  auto in_context(const std::string& key, Build&& build) const {
    try {
      return std::forward<Build>(build)();
    } catch (const InputError& e) {
      rethrow_in_context(key, e.what());
    } catch (const std::invalid_argument& e) {
      rethrow_in_context(key, e.what());
    }
  }

 private:
  [[noreturn]] void rethrow_in_context(const std::string& key, const std::string& message) const;

  const nlohmann::json& object_;
  std::string where_;
};

// The same checks for values that are not object members (array elements, spectra); `where` names the
// value ("file: film.resolution[0]").
double json_number(const nlohmann::json& value, const std::string& where, double min = kNoMinimum,
                   double max = kNoMaximum, bool min_exclusive = false);
long long json_integer(const nlohmann::json& value, const std::string& where, long long min, long long max);
bool json_boolean(const nlohmann::json& value, const std::string& where);
std::string json_string(const nlohmann::json& value, const std::string& where);
// An array of exactly `size` elements ("expected [width, height]" is `shape`).
const nlohmann::json& json_array(const nlohmann::json& value, const std::string& where, size_t size,
                                 const char* shape);
// An array of 3 numbers, in single precision or (positions) double.
Vec3 json_vec3(const nlohmann::json& value, const std::string& where);
Vec3d json_vec3d(const nlohmann::json& value, const std::string& where);

}  // namespace ochre
