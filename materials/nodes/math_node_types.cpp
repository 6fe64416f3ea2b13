#include "materials/nodes/math_node_types.h"

#include <string>

namespace ochre {

namespace {

int promotion_rank(SocketType t) {
  switch (t) {
    case SocketType::kFloat:
      return 0;
    case SocketType::kColour:
      return 1;
    case SocketType::kSpectrum:
      return 2;
    default:
      return -1;
  }
}

}  // namespace

SocketType promote_values(SocketType a, SocketType b, const char* b_name) {
  if (a == SocketType::kClosure || b == SocketType::kClosure)
    throw NodeError(b_name, "a closure cannot be combined with a value here");
  if (a == SocketType::kVector || b == SocketType::kVector) {
    const SocketType other = a == SocketType::kVector ? b : a;
    if (other != SocketType::kVector && other != SocketType::kFloat)
      throw NodeError(b_name, std::string("type mismatch: a vector cannot be combined with a ") +
                                  to_string(other) + " (vector <-> colour is not converted)");
    return SocketType::kVector;
  }
  return promotion_rank(a) >= promotion_rank(b) ? a : b;
}

SocketType combine_operands(SocketType a, SocketType b, const char* verb) {
  const bool a_closure = a == SocketType::kClosure, b_closure = b == SocketType::kClosure;
  if (a_closure && b_closure) return SocketType::kClosure;
  if (a_closure || b_closure) {
    const char* value_name = a_closure ? "b" : "a";
    throw NodeError(value_name, std::string("type mismatch: cannot ") + verb + " a closure and a " +
                                    to_string(a_closure ? b : a) + " (both operands must be closures)");
  }
  return promote_values(a, b, "b");
}

bool constant_equals(const NodeValue& v, float x) {
  switch (v.type) {
    case SocketType::kFloat:
      return v.f == x;
    case SocketType::kColour:
      return v.colour.r == x && v.colour.g == x && v.colour.b == x;
    case SocketType::kVector:
      return v.vector.x == x && v.vector.y == x && v.vector.z == x;
    case SocketType::kSpectrum:
      return v.spectrum->is_constant() && v.spectrum->eval(550.0f) == x;
    case SocketType::kClosure:
      return false;
  }
  return false;
}

}  // namespace ochre
