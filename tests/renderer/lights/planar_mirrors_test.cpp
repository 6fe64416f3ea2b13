// Planar mirrors (renderer/lights/planar_mirrors.h): which meshes qualify, the reflection geometry, and the
// selection of (mirror, light) pairs.

#include "renderer/lights/planar_mirrors.h"

#include <gtest/gtest.h>

#include "renderer/geometry/transform.h"
#include "renderer/shapes/procedural_shapes.h"
#include "support/test_material.h"

namespace ochre::planar_mirrors_test {
namespace {

std::shared_ptr<const CompiledMaterial> material(const char* json) {
  return test::compile_test_material(json);
}

// A 2 x 3 plane tilted about x by 30 degrees and moved: its plane is not an axis plane.
Mesh tilted_plane() {
  Mesh mesh = make_plane({2, 3});
  mesh.transform(Transform::translate({0.5f, -1, 2}) * Transform::rotate(30.0f, {1, 0, 0}));
  return mesh;
}

TEST(PlanarMirrors, SmoothConductorsAndBlackGlassPlanesAreMirrors) {
  for (const char* json :
       {R"({"type": "conductor", "metal": "Au"})", R"({"type": "conductor", "eta": 0, "k": 1})",
        R"({"type": "dielectric", "ior": 1.5, "opaque": 1})"}) {
    const auto mirror = planar_mirror(tilted_plane(), 3, *material(json));
    ASSERT_TRUE(mirror) << json;
    EXPECT_EQ(mirror->mesh, 3);
    EXPECT_NEAR(std::abs(mirror->normal.z), std::cos(30.0 * M_PI / 180.0), 1e-6) << json;
    EXPECT_NEAR(std::abs(mirror->normal.y), 0.5, 1e-6) << json;
    EXPECT_NEAR(mirror->area, 6.0f, 1e-5f);
    for (const Vec3& p : tilted_plane().positions) EXPECT_NEAR(mirror->signed_distance(p), 0.0f, 1e-6f);
  }
}

TEST(PlanarMirrors, OtherSurfacesAreNot) {
  const Mesh plane = tilted_plane();
  // Materials: rough, refracting, diffuse, a mirror mixed with a diffuse lobe, a textured weight.
  for (const char* json : {R"({"type": "conductor", "metal": "Au", "roughness": 0.1})",
                           R"({"type": "dielectric", "ior": 1.5})", R"({"type": "lambert", "color": 0.5})",
                           R"({"nodes": {"m": {"type": "conductor", "metal": "Ag"},
                                         "d": {"type": "lambert"},
                                         "out": {"type": "add", "a": {"link": "m"}, "b": {"link": "d"}}},
                               "output": "out"})"})
    EXPECT_FALSE(planar_mirror(plane, 0, *material(json))) << json;

  const auto gold = material(R"({"type": "conductor", "metal": "Au"})");
  // Geometry: a sphere, a bent plane (one vertex lifted), shading normals that are not the plane's.
  EXPECT_FALSE(planar_mirror(make_sphere(1.0f, 8), 0, *gold));
  Mesh bent = make_plane({2, 2});
  bent.positions[0].z += 1e-3f;
  EXPECT_FALSE(planar_mirror(bent, 0, *gold));
  Mesh smooth = make_plane({2, 2});
  smooth.normals.assign(smooth.positions.size(), Vec3(0, 0, 1));
  EXPECT_TRUE(planar_mirror(smooth, 0, *gold));
  smooth.normals[1] = normalize(Vec3(0.05f, 0, 1));
  EXPECT_FALSE(planar_mirror(smooth, 0, *gold));
}

TEST(PlanarMirrors, ReflectionKeepsDistancesAndMapsThePlaneToItself) {
  const auto mirror = planar_mirror(tilted_plane(), 0, *material(R"({"type": "conductor", "metal": "Ag"})"));
  ASSERT_TRUE(mirror);
  const Vec3 x{0.3f, 2.0f, -1.0f}, y{-1.0f, 0.5f, 4.0f};
  const Vec3 x_image = mirror->reflect_point(x);
  EXPECT_NEAR(mirror->signed_distance(x_image), -mirror->signed_distance(x), 1e-5f);
  EXPECT_NEAR(length(mirror->reflect_point(x_image) - x), 0.0f, 1e-5f);
  EXPECT_NEAR(length(x_image - y), length(mirror->reflect_point(y) - x), 1e-5f);
  // A direction reflected twice is itself; its component along the normal changes sign.
  const Vec3 d = normalize(Vec3(1, 2, 3));
  EXPECT_NEAR(dot(mirror->reflect_direction(d), mirror->normal), -dot(d, mirror->normal), 1e-6f);
  EXPECT_NEAR(length(mirror->reflect_direction(mirror->reflect_direction(d)) - d), 0.0f, 1e-6f);
}

TEST(PlanarMirrors, PairsAreChosenInProportionToTheLightsPower) {
  std::vector<Mesh> meshes{tilted_plane(), make_sphere(1.0f, 8), make_plane({1, 1})};
  std::vector<std::shared_ptr<const CompiledMaterial>> materials{
      material(R"({"type": "conductor", "metal": "Au"})"), material(R"({"type": "lambert"})")};
  meshes[0].material = 0;
  meshes[1].material = 0;  // gold, but not planar
  meshes[2].material = 0;
  MirrorLights mirrors;
  mirrors.build(meshes, materials, 3, 1);  // light 1 is at infinity: no image
  mirrors.update_selection(Distribution1D({0.5, 0.3, 0.2}));
  ASSERT_EQ(mirrors.mirrors().size(), 2u);
  EXPECT_EQ(mirrors.mirrors()[0].mesh, 0);  // the largest first
  EXPECT_EQ(mirrors.mirror_of_mesh(0), 0);
  EXPECT_EQ(mirrors.mirror_of_mesh(1), -1);
  EXPECT_EQ(mirrors.mirror_of_mesh(2), 1);
  // Lights 0 and 2 with weights 0.5 : 0.2, the same for both mirrors.
  EXPECT_NEAR(mirrors.pmf(0, 0), 0.5 / 1.4, 1e-6);
  EXPECT_NEAR(mirrors.pmf(1, 2), 0.2 / 1.4, 1e-6);
  EXPECT_EQ(mirrors.pmf(0, 1), 0.0f);
  int counts[2][3] = {};
  const int n = 7000;
  for (int i = 0; i < n; ++i) {
    const MirrorLights::Choice c = mirrors.sample((i + 0.5f) / n);
    ++counts[c.mirror == &mirrors.mirrors()[0] ? 0 : 1][c.light];
    EXPECT_EQ(c.pmf, mirrors.pmf(c.mirror == &mirrors.mirrors()[0] ? 0 : 1, c.light));
  }
  EXPECT_EQ(counts[0][1] + counts[1][1], 0);
  EXPECT_NEAR(counts[0][0], n * 0.5 / 1.4, 2);
  EXPECT_NEAR(counts[1][2], n * 0.2 / 1.4, 2);
}

}  // namespace
}  // namespace ochre::planar_mirrors_test
