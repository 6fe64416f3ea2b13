#pragma once
// Literal constants written in a scene: a number is a float, [r, g, b] a colour and
// {"vector": [x, y, z]} a vector. (Spectrum literals {"name": ...} / {"file": ...} need the
// resource resolver and are read by the graph parser.)

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "materials/nodes/node_value.h"

namespace ochre {

// The literal `j` stands for, nullopt when `j` is not of a literal form. Throws
// std::invalid_argument with a description when it has a literal form with bad contents
// (wrong length, non-numbers, NaN or infinite numbers).
std::optional<NodeValue> literal_value(const nlohmann::json& j);

// The scene text of a JSON value, shortened for messages.
std::string json_excerpt(const nlohmann::json& j);
// The shortest text that reads back as `x` ("1e-50", "0.1", "179"), for messages.
std::string number_text(double x);
std::string number_text(float x);

}  // namespace ochre
