#pragma once
// The largest scene coordinate ochre traces. Embree refuses (asserts on) rays whose origin has a component
// beyond about 1.8e18; camera positions and every vertex are held within +-1e15 scene units, so that every
// ray origin (camera, hit points, points mirrored in a plane) stays far inside that range. Scenes beyond it
// are refused at load with the item and parameter named.

#include <cmath>
#include <string>

#include "materials/core/vec3.h"

namespace ochre {

inline constexpr float kMaxSceneCoordinate = 1e15f;

inline bool within_scene_limit(const Vec3& p) {
  return std::fabs(p.x) <= kMaxSceneCoordinate && std::fabs(p.y) <= kMaxSceneCoordinate &&
         std::fabs(p.z) <= kMaxSceneCoordinate;
}

// The end of every message refusing a coordinate beyond the limit, e.g. "lies " + beyond_scene_limit().
inline std::string beyond_scene_limit() {
  return "beyond +-1e15, the largest coordinate ochre traces";
}

}  // namespace ochre
