#pragma once
// JSON text -> nlohmann::json, rejecting an object that repeats a key. JSON parsers (nlohmann's too)
// silently keep the last of two equal keys, so a scene with "radius" twice would render with a value the
// author may not have meant; this is an InputError naming the file, the JSON path and the key:
//   scene.json: shapes[0].radius: duplicate key "radius" (a key may appear once per object)
// Syntax errors are nlohmann::json::parse_error as from nlohmann::json::parse (comments allowed).

#include <nlohmann/json.hpp>
#include <string>

namespace ochre {

nlohmann::json parse_json_rejecting_duplicate_keys(const std::string& text, const std::string& file);

}  // namespace ochre
