#include "renderer/shapes/procedural_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "spectra/input_error.h"

namespace ochre::procedural_shapes_test {
namespace {

Vec3 face_normal(const Mesh& m, size_t t) {
  const Vec3 &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
             &c = m.positions[m.indices[3 * t + 2]];
  return cross(b - a, c - a);
}

void expect_uvs_in_unit_square(const Mesh& m) {
  for (const Vec2& uv : m.uvs) {
    EXPECT_GE(uv.x, 0.0f);
    EXPECT_LE(uv.x, 1.0f);
    EXPECT_GE(uv.y, 0.0f);
    EXPECT_LE(uv.y, 1.0f);
  }
}

TEST(ProceduralShapes, PlaneAreaNormalsAndUvs) {
  const Mesh plane = make_plane({3, 2});
  EXPECT_NO_THROW(plane.validate("plane"));
  EXPECT_EQ(plane.triangle_count(), 2u);
  EXPECT_FLOAT_EQ(plane.surface_area(), 6.0f);
  for (size_t t = 0; t < 2; ++t) EXPECT_GT(face_normal(plane, t).z, 0.0f);
  for (const Vec3& n : plane.normals) EXPECT_EQ(n, Vec3(0, 0, 1));
  // u along +x, v along +y, (0, 0) at the (-x, -y) corner.
  for (size_t i = 0; i < plane.positions.size(); ++i) {
    EXPECT_FLOAT_EQ(plane.uvs[i].x, plane.positions[i].x / 3 + 0.5f);
    EXPECT_FLOAT_EQ(plane.uvs[i].y, plane.positions[i].y / 2 + 0.5f);
  }
  EXPECT_GT(plane.positions.capacity(), plane.positions.size());  // padding for Accel
}

TEST(ProceduralShapes, DiskAreaConvergesToPiRSquared) {
  const float r = 1.5f;
  const Mesh disk = make_disk(r, 256);
  EXPECT_NO_THROW(disk.validate("disk"));
  EXPECT_EQ(disk.triangle_count(), 256u);
  EXPECT_NEAR(disk.surface_area() / (kPi * r * r), 1.0f, 1e-3f);
  // The exact polygon area (n/2) r^2 sin(2 pi / n).
  EXPECT_NEAR(disk.surface_area(), 128.0 * r * r * std::sin(2 * M_PI / 256), 1e-4);
  for (size_t t = 0; t < disk.triangle_count(); ++t) EXPECT_GT(face_normal(disk, t).z, 0.0f);
  expect_uvs_in_unit_square(disk);
  for (size_t i = 0; i < disk.positions.size(); ++i) {
    EXPECT_NEAR(disk.uvs[i].x, (disk.positions[i].x / r + 1) / 2, 1e-6f);
    EXPECT_NEAR(disk.uvs[i].y, (disk.positions[i].y / r + 1) / 2, 1e-6f);
  }
  EXPECT_GT(disk.positions.capacity(), disk.positions.size());
}

TEST(ProceduralShapes, SphereAreaNormalsAndUvs) {
  const float r = 2.0f;
  const Mesh sphere = make_sphere(r, 128);
  EXPECT_NO_THROW(sphere.validate("sphere"));
  // Inscribed polyhedron: area slightly below 4 pi r^2, converging as 1/n^2.
  const float ratio = sphere.surface_area() / (4 * kPi * r * r);
  EXPECT_LT(ratio, 1.0f);
  EXPECT_GT(ratio, 0.999f);
  EXPECT_LT(make_sphere(r, 16).surface_area() / (4 * kPi * r * r), ratio);
  // UV sphere with n bands: 2n * 2 * (n - 1) triangles (one per quad at the poles).
  EXPECT_EQ(sphere.triangle_count(), 2u * 256u * 127u);
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    const Vec3& p = sphere.positions[i];
    EXPECT_NEAR(length(sphere.normals[i]), 1.0f, 1e-6f);
    EXPECT_NEAR(length(p), r, 1e-5f);
    EXPECT_NEAR(dot(sphere.normals[i], p / r), 1.0f, 1e-6f);
    // v = theta / pi from the south pole: z = -r cos(pi v).
    EXPECT_NEAR(p.z, -r * std::cos(kPi * sphere.uvs[i].y), 1e-5f);
  }
  expect_uvs_in_unit_square(sphere);
  for (size_t t = 0; t < sphere.triangle_count(); ++t) {
    const Vec3 n = face_normal(sphere, t);
    ASSERT_GT(length(n), 0.0f) << "degenerate triangle " << t;
    ASSERT_GT(dot(n, sphere.positions[sphere.indices[3 * t]]), 0.0f) << "inward triangle " << t;
  }
}

TEST(ProceduralShapes, SphereUIsLongitude) {
  const Mesh sphere = make_sphere(1, 8);
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    const Vec3& p = sphere.positions[i];
    if (std::hypot(p.x, p.y) < 1e-3f) continue;  // poles
    float phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += 2 * kPi;
    // u = phi / 2 pi modulo 1 (the seam column has u = 1 at phi = 0).
    EXPECT_NEAR(std::remainder(sphere.uvs[i].x - phi / (2 * kPi), 1.0f), 0.0f, 1e-5f) << i;
  }
}

TEST(ProceduralShapes, CubeFacesPointOutwardWithMitsubasUvs) {
  const Mesh cube = make_cube({2, 4, 6});
  EXPECT_NO_THROW(cube.validate("cube"));
  EXPECT_EQ(cube.triangle_count(), 12u);
  EXPECT_FLOAT_EQ(cube.surface_area(), 2 * (2 * 4 + 4 * 6 + 2 * 6));
  for (size_t t = 0; t < cube.triangle_count(); ++t) {
    const Vec3 n = cube.normals[cube.indices[3 * t]];
    const Vec3 centre = (cube.positions[cube.indices[3 * t]] + cube.positions[cube.indices[3 * t + 1]] +
                         cube.positions[cube.indices[3 * t + 2]]) *
                        (1.0f / 3.0f);
    EXPECT_GT(dot(face_normal(cube, t), n), 0.0f) << t;  // winding agrees with the normal
    EXPECT_GT(dot(centre, n), 0.0f) << t;                // which points outward
  }
  expect_uvs_in_unit_square(cube);
  // The -y face (Mitsuba's first): corners (1,-1,-1), (1,-1,1), (-1,-1,1), (-1,-1,-1) with Mitsuba's uvs
  // (0,1), (1,1), (1,0), (0,0), so ochre's (upward v) are (0,0), (1,0), (1,1), (0,1).
  EXPECT_EQ(cube.positions[0], Vec3(1, -2, -3));
  EXPECT_EQ(cube.uvs[0].x, 0.0f);
  EXPECT_EQ(cube.uvs[0].y, 0.0f);
  EXPECT_EQ(cube.positions[2], Vec3(-1, -2, 3));
  EXPECT_EQ(cube.uvs[2].x, 1.0f);
  EXPECT_EQ(cube.uvs[2].y, 1.0f);
}

// The lateral area of the polygonal frustum of n flat trapezoids: each has parallel sides 2 r1 sin(pi/n) and
// 2 r2 sin(pi/n) at the height sqrt(h^2 + (r1 - r2)^2 cos^2(pi/n)) from each other (r2 = 0: triangles).
// Normals: unit, perpendicular to the slant, outward.
TEST(ProceduralShapes, ConeAreaNormalsAndUvs) {
  for (const float top : {0.0f, 0.5f, 1.5f}) {
    const float r = 1.0f, h = 2.0f;
    const int n = 256;
    const Mesh cone = make_cone(r, top, h, n);
    EXPECT_NO_THROW(cone.validate("cone"));
    EXPECT_EQ(cone.triangle_count(), top > 0 ? 2u * n : 1u * n);
    const double half = M_PI / n;
    const double exact =
        n * (double(r) + top) * std::sin(half) * std::hypot(double(h), (double(r) - top) * std::cos(half));
    EXPECT_NEAR(cone.surface_area() / exact, 1.0, 1e-5) << top;
    for (size_t t = 0; t < cone.triangle_count(); ++t) {
      const Vec3 ng = face_normal(cone, t), centre = cone.positions[cone.indices[3 * t]];
      EXPECT_GT(dot(ng, Vec3(centre.x, centre.y, 0.0f)), 0.0f) << "triangle " << t << " faces inward";
    }
    for (size_t i = 0; i < cone.positions.size(); ++i) {
      const Vec3 &p = cone.positions[i], &nrm = cone.normals[i];
      EXPECT_NEAR(length(nrm), 1.0f, 1e-6f);
      // Along the slant at the vertex's angle: (top - r) (cos, sin) radially and h up; the normal is
      // perpendicular to it.
      const float phi = 2.0f * float(M_PI) * cone.uvs[i].x;
      const Vec3 slant_dir{(top - r) * std::cos(phi), (top - r) * std::sin(phi), h};
      EXPECT_NEAR(dot(nrm, slant_dir) / length(slant_dir), 0.0f, 1e-5f);
      EXPECT_FLOAT_EQ(cone.uvs[i].y, p.z / h);
    }
  }
  EXPECT_THROW(make_cone(1, -0.5f, 2, 16), InputError);
  EXPECT_THROW(make_cone(1, 0.5f, 0, 16), InputError);
  EXPECT_THROW(make_cone(1, 0.5f, 2, 2), InputError);
}

TEST(ProceduralShapes, FlipNormalsTurnsTheSurfaceAndFlipUvVTheImage) {
  Mesh plane = make_plane({2, 2});
  flip_normals(plane);
  EXPECT_NO_THROW(plane.validate("plane"));
  for (size_t t = 0; t < 2; ++t) EXPECT_LT(face_normal(plane, t).z, 0.0f);
  for (const Vec3& n : plane.normals) EXPECT_EQ(n, Vec3(0, 0, -1));
  flip_uv_v(plane);
  for (size_t i = 0; i < plane.positions.size(); ++i)
    EXPECT_FLOAT_EQ(plane.uvs[i].y, 0.5f - plane.positions[i].y / 2);
}

TEST(ProceduralShapes, BadParametersAreInputErrors) {
  EXPECT_THROW(make_cube({1, 0, 1}), InputError);
  EXPECT_THROW(make_plane({0, 1}), InputError);
  EXPECT_THROW(make_plane({1, NAN}), InputError);
  EXPECT_THROW(make_disk(-1), InputError);
  EXPECT_THROW(make_disk(1, 2), InputError);
  EXPECT_THROW(make_sphere(1, 1), InputError);
  EXPECT_THROW(make_sphere(INFINITY, 8), InputError);
}

}  // namespace
}  // namespace ochre::procedural_shapes_test
