#pragma once
// Typed values during lowering: a scalar, vec2 or vec3 as graph nodes.

#include <array>
#include <string_view>

#include "expr/graph.h"

namespace sdfwb::expr {

// The value of a type is its number of components.
enum class Type { Scalar = 1, Vec2 = 2, Vec3 = 3 };

// "scalar", "vec2", "vec3".
std::string_view typeName(Type type);
inline Type vectorType(int size) { return static_cast<Type>(size); }

struct Value {
  Type type = Type::Scalar;
  std::array<NodeId, 3> components{};

  int size() const { return static_cast<int>(type); }
  // Component i; a scalar broadcasts, so every index gives its one value.
  NodeId operator[](int i) const { return components[type == Type::Scalar ? 0 : i]; }

  static Value scalar(NodeId node) { return Value{Type::Scalar, {node, node, node}}; }
};

}  // namespace sdfwb::expr
