// A path's last bounce (from the vertex before max_depth) can find only emission. Where no ray can find
// light (no environment, no emissive surface: point, spot, sphere and flame lights are not geometry) the
// integrator leaves it out, and a last vertex whose material cannot emit is neither shaded nor lit.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::last_bounce_test {
namespace {

constexpr int kSize = 8;
constexpr uint32_t kSpp = 4;

// The camera inside a closed Lambert sphere lit by a point light at its centre: every ray hits the wall, so
// the ray counts are exact. `extra_light` adds a light of another kind.
LoadedScene inside_sphere(const std::string& extra_light) {
  const std::string text = R"({
    "camera": {"type": "perspective", "fov": 60, "eye": [0, 0, 0], "target": [0, 0, -1]},
    "film": {"resolution": [8, 8]},
    "integrator": {"spp": 4, "branches": 1, "max_depth": 3, "rr_depth": 16},
    "materials": {"wall": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "point", "position": [0, 0, 0], "intensity": 1})" +
                           extra_light + R"(],
    "shapes": [{"type": "sphere", "radius": 5, "subdivisions": 32, "material": "wall"}]
  })";
  return load_scene_json(nlohmann::json::parse(text), "inside.json", test::source_dir() / "inside.json");
}

TEST(LastBounce, LeftOutWhereNoRayCanFindLight) {
  const LoadedScene scene = inside_sphere("");
  EXPECT_FALSE(scene.scene->rays_find_emission());
  Film film(kSize, kSize);
  const RenderStats stats = render(*scene.scene, scene.job, film);
  EXPECT_GT(film.mean(kSize / 2, kSize / 2).y, 0.0f);
  const uint64_t paths = kSize * kSize * kSpp;
  // Camera ray, bounces to depths 1 and 2; the bounce to depth 3 could find only emission.
  EXPECT_EQ(stats.rays, paths * 3);
  EXPECT_EQ(stats.shadow_rays, paths * 3);  // a light sample at depths 0, 1 and 2
}

TEST(LastBounce, TakenWhereAnEnvironmentCanBeFound) {
  // The environment is out of sight inside the sphere, but a ray of another scene could find it.
  const LoadedScene scene = inside_sphere(R"(, {"type": "environment", "radiance": 1})");
  EXPECT_TRUE(scene.scene->rays_find_emission());
  Film film(kSize, kSize);
  const RenderStats stats = render(*scene.scene, scene.job, film);
  EXPECT_EQ(stats.rays, kSize * kSize * kSpp * 4);
}

}  // namespace
}  // namespace ochre::last_bounce_test
