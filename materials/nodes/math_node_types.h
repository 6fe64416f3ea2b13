#pragma once
// Shared typing of the polymorphic math nodes (add, multiply, mix): operand types promote along
// float < colour < spectrum, a float broadcasts to a vector, and closures combine only with
// closures (add, mix) or are scaled by a float, colour or spectrum (multiply).

#include <span>

#include "materials/nodes/node_definition.h"

namespace ochre {

// The common type of two value operands; throws NodeError naming `b_name` when they cannot meet
// (a vector with a colour or spectrum) or when either is a closure.
SocketType promote_values(SocketType a, SocketType b, const char* b_name);

// Types of a two-operand node whose operands are both values or both closures (add, mix's a and b).
// Throws NodeError naming the operand that breaks the rule.
SocketType combine_operands(SocketType a, SocketType b, const char* verb);

// True when a constant is exactly `x` everywhere (float, colour, vector, or a flat spectrum).
bool constant_equals(const NodeValue& v, float x);

}  // namespace ochre
