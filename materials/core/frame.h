#pragma once
// Frame: an orthonormal basis (s, t, n); local shading coordinates have z = n.

#include "materials/core/vec3.h"

namespace ochre {

struct Frame {
  Vec3 s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  // Basis around a unit normal (Duff et al. 2017, "Building an orthonormal basis, revisited").
  // The basis is continuous except across n.z = 0's sign flip; polarization frames must not
  // rely on it (see docs/polarization.md, 'Discontinuous reference frames').
  static Frame from_normal(const Vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    Frame f;
    f.s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    f.t = {b, sign + n.y * n.y * a, -n.y};
    f.n = n;
    return f;
  }
  // Basis with n and a preferred tangent direction (Gram-Schmidt).
  static Frame from_normal_tangent(const Vec3& n, const Vec3& tangent) {
    Vec3 s = tangent - n * dot(n, tangent);
    const float len = length(s);
    if (!(len > 1e-6f)) return from_normal(n);
    Frame f;
    f.n = n;
    f.s = s / len;
    f.t = cross(n, f.s);
    return f;
  }

  Vec3 to_local(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace ochre
