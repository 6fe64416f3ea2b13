#pragma once
// Cameras: perspective (pinhole) and orthographic. A camera maps a film position in
// normalised coordinates (x right, y down, both in [0,1)) to a world-space ray.

#include "materials/core/vec3.h"
#include "renderer/geometry/ray.h"

namespace ochre {

struct CameraBasis {
  Vec3 eye;
  Vec3 right, up, forward;  // orthonormal, right-handed: right x up = -forward
};

// The film axis a field of view is measured across (the "fov_axis" of a camera, as in Mitsuba 3):
// x (width), y (height), the diagonal, or the smaller / larger of width and height.
enum class FovAxis { X, Y, Diagonal, Smaller, Larger };

// The field of view in degrees across the shorter film axis that equals `fov_degrees` across `axis` of a
// width x height film (the same angle for Smaller).
double fov_across_shorter_axis(double fov_degrees, FovAxis axis, int width, int height);

// Basis looking from eye at target; `up` need not be orthogonal to the view direction.
CameraBasis camera_basis_look_at(const Vec3& eye, const Vec3& target, const Vec3& up);

// A ray cone (Akenine-Moller et al. 2019, "Texture Level of Detail Strategies for Real-Time Ray
// Tracing"): the footprint width at the origin and its growth per unit distance. Texture lookups use it
// to pick a filter width, so distant textured surfaces are filtered, not aliased.
struct RayCone {
  float width = 0.0f;   // world-space width at the ray origin
  float spread = 0.0f;  // radians: width grows by spread x distance
  float width_at(float distance) const { return width + spread * distance; }
};

class Camera {
 public:
  enum class Kind { Perspective, Orthographic };

  // fov_degrees: field of view across the shorter film axis (perspective).
  static Camera perspective(const CameraBasis& basis, float fov_degrees, int width, int height);
  // view_size: world-space extent of the shorter film axis (orthographic).
  static Camera orthographic(const CameraBasis& basis, float view_size, int width, int height);

  // film_x, film_y in pixels (continuous; pixel (i, j) covers [i, i+1) x [j, j+1), j = 0 at the top).
  Ray generate_ray(float film_x, float film_y) const;
  // The cone of one pixel: spread = pixel angle (perspective) or width = pixel size (orthographic).
  RayCone pixel_cone() const;
  Kind kind() const { return kind_; }
  const CameraBasis& basis() const { return basis_; }

 private:
  Kind kind_ = Kind::Perspective;
  CameraBasis basis_;
  float half_width_ = 1, half_height_ = 1;  // tangent of half-angles (perspective) or world half extents
  int width_ = 1, height_ = 1;
};

}  // namespace ochre
