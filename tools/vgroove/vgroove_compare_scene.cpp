#include "tools/vgroove/vgroove_compare_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_reference.h"
#include "renderer/shapes/groove_shapes.h"

namespace ochre {

namespace {

constexpr double kFrame = 1.0;            // the orthographic camera's size: the frame is 1 x 1
constexpr double kCameraDistance = 10.0;  // from the target (any distance outside the grooves will do)

// 17 significant digits: a double reads back exactly.
std::string exact_text(double x) {
  return fmt::format("{:.17g}", x);
}

std::string json(const Vec3d& v) {
  return fmt::format("[{}, {}, {}]", exact_text(v.x), exact_text(v.y), exact_text(v.z));
}

Vec3d view_direction(const CompareView& v) {
  return groove_direction(v.theta_deg * kDegD, v.phi_deg * kDegD);
}

// Straight down, the world's z cannot be the image's up.
Vec3d camera_up(const CompareView& v) {
  return v.theta_deg > 1.0 ? Vec3d{0, 0, 1} : Vec3d{0, 1, 0};
}

// The point where the orthographic ray through the image point a (a vector in the image plane from the
// frame's centre) meets the plane z = 0: the ray runs along -e.
Vec3d on_plane(const Vec3d& a, const Vec3d& e) {
  return a - e * (a.z / e.z);
}

struct Footprint {
  Vec3d right, up;  // the plane points of the image axes' unit vectors: the frame is
                    // {u right + v up : |u|, |v| <= kFrame / 2}
};

Footprint footprint(const CompareView& v) {
  const Vec3d e = view_direction(v);
  const Vec3d right = normalize(cross(e, camera_up(v)));
  return {on_plane(right, e), on_plane(cross(right, e), e)};
}

// The pitch that puts one groove period in each pixel along the image axis that crosses the grooves
// fastest: the image is periodic across the grooves, so every pixel's expected value is R and the pixels
// are independent estimates of it. Few periods also keep the plate's coordinates few pitches long, which
// keeps the ray-spawning bias small (shape_json below).
double groove_pitch(const CompareView& v) {
  const Footprint f = footprint(v);
  return std::max(std::abs(f.right.y), std::abs(f.up.y)) * kFrame / v.resolution;
}

// The plate's extent, centred on the target: the frame's footprint, plus room for a ray to run along a
// groove inside it (up to ceil(180 / alpha) reflections, each segment no longer than the groove's
// cross-section divided by the sine of its angle to the grooves), plus two pitches.
struct PlateSize {
  double across, along;  // y, x
};

PlateSize plate_size(const CompareView& v, double pitch) {
  const Footprint f = footprint(v);
  const double half = 0.5 * kFrame;
  const double x = half * (std::abs(f.right.x) + std::abs(f.up.x));
  const double y = half * (std::abs(f.right.y) + std::abs(f.up.y));
  const double facet = std::hypot(0.5 * pitch, groove_depth(pitch, v.alpha_deg));
  const double segment = std::max(pitch, facet);
  const Vec3d e = view_direction(v);
  const double run = (compare_max_depth(v.alpha_deg) * segment) * std::abs(e.x) / std::sqrt(1.0 - e.x * e.x);
  return {2.0 * (y + segment + 2.0 * pitch), 2.0 * (x + run + 2.0 * pitch)};
}

std::string facet_fields(const FacetIndex& f) {
  return f.mirror ? R"("metal": "mirror")"
                  : fmt::format(R"("eta": {}, "k": {})", exact_text(f.eta.real()), exact_text(-f.eta.imag()));
}

std::string material_json(GrooveSurface surface, const CompareView& v) {
  switch (surface) {
    case GrooveSurface::kExplicit:  // smooth facets; a flat `vgroove` is the ideal mirror
      return v.facet.mirror ? R"({"type": "vgroove", "alpha": 180, "metal": "mirror"})"
                            : fmt::format(R"({{"type": "conductor", {}}})", facet_fields(v.facet));
    case GrooveSurface::kAnalytic:
      return fmt::format(R"({{"type": "vgroove", "alpha": {}, {}}})", exact_text(v.alpha_deg),
                         facet_fields(v.facet));
    case GrooveSurface::kMicrogroove:
      return fmt::format(R"({{"type": "microgroove", "profile": "v", "alpha": {}, {}}})",
                         exact_text(v.alpha_deg), facet_fields(v.facet));
  }
  return {};
}

std::string shape_json(GrooveSurface surface, const CompareView& v) {
  const double pitch = groove_pitch(v);
  const PlateSize size = plate_size(v, pitch);
  if (surface != GrooveSurface::kExplicit)  // the plane's size is [x, y]
    return fmt::format(R"({{"type": "plane", "size": [{}, {}], "material": "surface"}})",
                       exact_text(size.along), exact_text(size.across));
  // One plate; its facets are cut into tiles 8 pitches long (the shape's default), which keeps the
  // ray-spawning bias of long facets small (docs/materials/vgroove.md).
  const int count = static_cast<int>(std::ceil(size.across / pitch));
  return fmt::format(
      R"({{"type": "groove_plate", "alpha": {}, "pitch": {}, "count": {}, "length": {}, "material": "surface"}})",
      exact_text(v.alpha_deg), exact_text(pitch), count, exact_text(size.along));
}

std::string settings_json(const CompareView& v, int max_depth) {
  return fmt::format(R"("film": {{"resolution": [{}, {}]}},
  "integrator": {{"spp": {}, "max_depth": {}, "rr_depth": {}, "seed": {}, "threads": {}}})",
                     v.resolution, v.resolution, v.spp, max_depth, max_depth, v.seed, v.threads);
}

}  // namespace

int compare_max_depth(double alpha_deg) {
  return static_cast<int>(std::ceil(180.0 / alpha_deg)) + 2;
}

std::string compare_scene_json(GrooveSurface surface, const CompareView& v) {
  const Vec3d eye = view_direction(v) * kCameraDistance;
  return fmt::format(R"({{
  "camera": {{"type": "orthographic", "size": {}, "eye": {}, "target": [0, 0, 0], "up": {}}},
  {},
  "materials": {{"surface": {}}},
  "lights": [{{"type": "environment", "radiance": 1}}],
  "shapes": [
  {}]
}}
)",
                     exact_text(kFrame), json(eye), json(camera_up(v)),
                     settings_json(v, compare_max_depth(v.alpha_deg)), material_json(surface, v),
                     shape_json(surface, v));
}

std::string environment_scene_json(const CompareView& v) {
  return fmt::format(R"({{
  "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0]}},
  {},
  "materials": {{}},
  "lights": [{{"type": "environment", "radiance": 1}}],
  "shapes": []
}}
)",
                     exact_text(kFrame), settings_json(v, compare_max_depth(v.alpha_deg)));
}

}  // namespace ochre
