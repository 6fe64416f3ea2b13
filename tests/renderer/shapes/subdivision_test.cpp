// Subdivision surfaces: OBJ control-mesh import (welding, crease tags), convergence of Catmull-Clark
// refinement to OpenSubdiv's limit surface and to the Halstead et al. 1993 limit mask, Loop limit
// positions (Hoppe et al. 1994 mask), triangle counts, face-varying uv continuity and seams, infinitely
// sharp creases, limit normals and option parsing (the 1-million-triangle timing is
// `ochre-bench --micro subdivision`).

#include "renderer/shapes/subdivision.h"

#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::subdivision_test {
namespace {

using namespace OpenSubdiv;

ControlMesh cube() {
  ControlMesh mesh;
  mesh.name = "cube";
  mesh.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  mesh.face_sizes = {4, 4, 4, 4, 4, 4};
  mesh.face_vertices = {4, 5, 6, 7, 3, 2, 1, 0, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  return mesh;
}

struct P3 {
  Vec3 v;
  void Clear() { v = {}; }
  void AddWithWeight(const P3& s, float w) { v += s.v * w; }
};

// Limit positions and normals (OpenSubdiv PrimvarRefiner::Limit) of the level-`level` vertices of a
// Catmull-Clark (or Loop) surface with interpolated boundaries, computed here independently of
// subdivide().
void osd_limit(const ControlMesh& control, Sdc::SchemeType scheme, int level, std::vector<Vec3>& positions,
               std::vector<Vec3>& normals) {
  Far::TopologyDescriptor desc;
  desc.numVertices = int(control.positions.size());
  desc.numFaces = int(control.face_sizes.size());
  desc.numVertsPerFace = control.face_sizes.data();
  desc.vertIndicesPerFace = control.face_vertices.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, options)));
  Far::TopologyRefiner::UniformOptions uniform(level);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  Far::PrimvarRefiner primvar(*refiner);
  std::vector<P3> src(control.positions.size());
  for (size_t i = 0; i < src.size(); ++i) src[i].v = control.positions[i];
  for (int l = 1; l <= level; ++l) {
    std::vector<P3> dst(size_t(refiner->GetLevel(l).GetNumVertices()));
    primvar.Interpolate(l, src, dst);
    src = std::move(dst);
  }
  std::vector<P3> limit(src.size()), du(src.size()), dv(src.size());
  primvar.Limit(src, limit, du, dv);
  positions.clear();
  normals.clear();
  for (size_t i = 0; i < src.size(); ++i) {
    positions.push_back(limit[i].v);
    normals.push_back(normalize(cross(du[i].v, dv[i].v)));
  }
}

float max_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  float worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, length(a[i] - b[i]));
  return worst;
}

TEST(ControlMeshImport, WeldsUvSeamsAndReadsCreaseTags) {
  const ControlMesh mesh =
      import_control_mesh(test::source_dir() / "tests/data/cube_quads.obj", Transform::translate({0, 0, 5}));
  EXPECT_EQ(mesh.positions.size(), 8u);  // 24 corners with distinct uvs welded back to 8 vertices
  ASSERT_EQ(mesh.face_sizes, std::vector<int>(6, 4));
  EXPECT_EQ(mesh.face_uv_indices.size(), 24u);
  EXPECT_GT(mesh.uvs.size(), 8u);
  ASSERT_EQ(mesh.crease_edges.size(), 1u);
  EXPECT_FLOAT_EQ(mesh.crease_sharpness[0], 10.0f);
  const Vec3 a = mesh.positions[size_t(mesh.crease_edges[0].first)];
  const Vec3 b = mesh.positions[size_t(mesh.crease_edges[0].second)];
  EXPECT_EQ(a, Vec3(-1, -1, 6));  // OBJ vertex 4 (0-based), translated
  EXPECT_EQ(b, Vec3(1, -1, 6));
  ASSERT_EQ(mesh.corner_vertices.size(), 2u);
  EXPECT_EQ(mesh.positions[size_t(mesh.corner_vertices[1])], Vec3(1, -1, 6));
}

TEST(ControlMeshImport, MissingFileNamesIt) {
  try {
    import_control_mesh("/nonexistent/cage.obj", Transform::identity());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/cage.obj"), std::string::npos);
  }
}

TEST(Subdivision, TriangleCountsPerScheme) {
  const ControlMesh tetra = import_control_mesh(test::source_dir() / "tests/data/tetrahedron.obj", {});
  for (int level = 0; level <= 4; ++level) {
    const int quads = level == 0 ? 1 : 1 << (2 * level);
    EXPECT_EQ(subdivide(cube(), {SubdivisionScheme::Auto, level}).triangle_count(), size_t(6 * 2 * quads));
    EXPECT_EQ(subdivide(tetra, {SubdivisionScheme::Auto, level}).triangle_count(), size_t(4 * quads))
        << "Loop";
  }
  // Catmull-Clark on triangles: each triangle becomes 3 quads at level 1.
  EXPECT_EQ(subdivide(tetra, {SubdivisionScheme::CatmullClark, 1}).triangle_count(), size_t(4 * 3 * 2));
  EXPECT_THROW(subdivide(cube(), {SubdivisionScheme::Loop, 1}), InputError);
  EXPECT_THROW(subdivide(cube(), {SubdivisionScheme::Auto, 9}), InputError);
}

TEST(Subdivision, CatmullClarkConvergesToTheLimitSurface) {
  const ControlMesh control = cube();
  float previous = 1e9f;
  for (int level = 1; level <= 4; ++level) {
    const Mesh mesh = subdivide(control, {SubdivisionScheme::CatmullClark, level});
    std::vector<Vec3> limit, limit_normals;
    osd_limit(control, Sdc::SCHEME_CATMARK, level, limit, limit_normals);
    ASSERT_EQ(mesh.positions.size(), limit.size());  // no uvs: output vertex i = refined vertex i
    const float distance = max_distance(mesh.positions, limit);
    std::printf("Catmull-Clark cube level %d: %zu triangles, max |refined - limit| = %.6f\n", level,
                mesh.triangle_count(), distance);
    EXPECT_LT(distance, previous * 0.5f);
    previous = distance;
    for (size_t i = 0; i < limit.size(); ++i) {
      EXPECT_NEAR(length(mesh.normals[i]), 1.0f, 1e-5f);
      EXPECT_GT(dot(mesh.normals[i], limit_normals[i]), 0.99999f) << "limit normal at vertex " << i;
      EXPECT_GT(dot(mesh.normals[i], mesh.positions[i]), 0.5f * length(mesh.positions[i])) << "outward";
    }
    // Halstead, Kass & DeRose 1993: the limit of a valence-n vertex of an all-quad mesh is
    // (n^2 v + 4 sum(edge neighbours) + sum(face diagonals)) / (n (n + 5)); for a cube corner
    // (n = 3): (9 + 4 - 1) / 24 = 0.5 per coordinate.
    for (size_t i = 0; i < limit.size(); ++i) {
      const Vec3 p = mesh.positions[i];
      if (std::fabs(p.x - p.y) < 1e-6f && std::fabs(p.y - p.z) < 1e-6f && p.x > 0) {
        EXPECT_NEAR(limit[i].x, 0.5f, 1e-5f);
      }
    }
  }
  EXPECT_LT(previous, 0.01f);
}

TEST(Subdivision, LoopOctahedronVertexReachesItsLimitPosition) {
  const ControlMesh octa = import_control_mesh(test::source_dir() / "tests/data/octahedron.obj", {});
  // Loop limit mask (Hoppe et al. 1994): v_inf = (1 - n chi) v + chi sum(neighbours), chi = 1 / (n + 3 /
  // (8 beta)), beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. For v = (1, 0, 0), n = 4, sum = 0.
  const double n = 4, beta = (5.0 / 8 - std::pow(3.0 / 8 + std::cos(2 * M_PI / n) / 4, 2)) / n;
  const double chi = 1 / (n + 3 / (8 * beta)), expected = 1 - n * chi;
  for (int level = 2; level <= 6; level += 2) {
    const Mesh mesh = subdivide(octa, {SubdivisionScheme::Auto, level});
    EXPECT_EQ(mesh.triangle_count(), size_t(8) << (2 * level));
    float x_on_axis = 0;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      const Vec3 p = mesh.positions[i];
      if (p.y == 0 && p.z == 0 && p.x > 0) x_on_axis = p.x;
      EXPECT_GT(dot(mesh.normals[i], p), 0.0f) << "outward";
      EXPECT_LE(std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z), 1.0f + 1e-6f) << "inside the hull";
    }
    std::printf("Loop octahedron level %d: vertex on +x at %.6f, limit %.6f\n", level, x_on_axis, expected);
    EXPECT_NEAR(x_on_axis, expected, level == 6 ? 1e-4 : 0.02);
  }
}

TEST(Subdivision, InfinitelySharpCreaseBetweenCornersStaysStraight) {
  for (int sharp = 0; sharp <= 1; ++sharp) {
    ControlMesh control = cube();
    if (sharp) {
      control.crease_edges = {{4, 5}};  // (-1,-1,1) - (1,-1,1)
      control.crease_sharpness = {10};
      control.corner_vertices = {4, 5};
      control.corner_sharpness = {10, 10};
    }
    const int level = 3;
    const Mesh mesh = subdivide(control, {SubdivisionScheme::CatmullClark, level});
    std::vector<float> xs;
    for (const Vec3& p : mesh.positions)
      if (std::fabs(p.y + 1) < 1e-6f && std::fabs(p.z - 1) < 1e-6f) xs.push_back(p.x);
    if (!sharp) {
      EXPECT_TRUE(xs.empty()) << "a smooth cube rounds its edges";
      continue;
    }
    ASSERT_EQ(xs.size(), size_t((1 << level) + 1));
    std::sort(xs.begin(), xs.end());
    for (size_t j = 0; j < xs.size(); ++j) EXPECT_NEAR(xs[j], -1 + 2 * float(j) / float(1 << level), 1e-6f);
  }
}

TEST(Subdivision, FaceVaryingUvsAreContinuousOrSplitAtSeams) {
  const int level = 3;
  const ControlMesh continuous = quad_grid_control_mesh(2, 1);
  const Mesh smooth = subdivide(continuous, {SubdivisionScheme::CatmullClark, level});
  const size_t refined_vertices = size_t((2 * 8 + 1) * (8 + 1));
  EXPECT_EQ(smooth.positions.size(), refined_vertices);
  for (size_t i = 0; i < smooth.positions.size(); ++i) {
    // Catmull-Clark (with B-spline boundaries) reproduces affine functions: uv stays (x + 1) / 2, y.
    EXPECT_NEAR(smooth.uvs[i].x, (smooth.positions[i].x + 1) / 2, 1e-6f);
    EXPECT_NEAR(smooth.uvs[i].y, smooth.positions[i].y, 1e-6f);
    EXPECT_NEAR(smooth.normals[i].z, 1.0f, 1e-6f);
  }
  // Seam along x = 0: the right face gets its own uv values, shifted by 0.25 in u.
  ControlMesh seamed = continuous;
  for (int v : {1, 2, 4, 5})
    seamed.uvs.push_back({continuous.uvs[size_t(v)].x + 0.25f, continuous.uvs[size_t(v)].y});
  seamed.face_uv_indices = {0, 1, 4, 3, 6, 7, 9, 8};
  const Mesh split = subdivide(seamed, {SubdivisionScheme::CatmullClark, level});
  EXPECT_EQ(split.positions.size(), refined_vertices + (1 << level) + 1);
  EXPECT_EQ(split.triangle_count(), smooth.triangle_count());
  std::map<std::pair<float, float>, int> copies;
  for (size_t i = 0; i < split.positions.size(); ++i) {
    const Vec3 p = split.positions[i];
    const bool right = p.x > 1e-6f || (std::fabs(p.x) <= 1e-6f && split.uvs[i].x > 0.6f);
    EXPECT_NEAR(split.uvs[i].x, (p.x + 1) / 2 + (right ? 0.25f : 0.0f), 1e-6f) << p.x << " " << p.y;
    EXPECT_NEAR(split.uvs[i].y, p.y, 1e-6f);
    ++copies[{p.x, p.y}];
  }
  for (const auto& [xy, count] : copies)
    EXPECT_EQ(count, std::fabs(xy.first) <= 1e-6f ? 2 : 1) << xy.first << " " << xy.second;
}

TEST(Subdivision, ImportedCageWithSeamsCreasesAndColours) {
  ControlMesh control =
      import_control_mesh(test::source_dir() / "tests/data/cube_quads.obj", Transform::identity());
  control.colours.assign(control.positions.size(), Vec3{0.2f, 0.4f, 0.6f});
  const int level = 2;
  const Mesh mesh = subdivide(control, {SubdivisionScheme::Auto, level});
  EXPECT_EQ(mesh.triangle_count(), size_t(6 * 16 * 2));
  std::map<std::tuple<float, float, float>, Vec3> normal_at;
  int on_crease = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 p = mesh.positions[i];
    EXPECT_NEAR(mesh.colours[i].x, 0.2f, 1e-6f);  // weights sum to one: a constant stays constant
    EXPECT_NEAR(mesh.colours[i].z, 0.6f, 1e-6f);
    if (std::fabs(p.y + 1) < 1e-6f && std::fabs(p.z - 1) < 1e-6f) ++on_crease;
    // Every cube edge is a uv seam: copies of one vertex share position and limit normal.
    const auto [it, inserted] = normal_at.try_emplace({p.x, p.y, p.z}, mesh.normals[i]);
    if (!inserted) {
      EXPECT_EQ(it->second, mesh.normals[i]);
    }
  }
  EXPECT_EQ(normal_at.size(), size_t(6 * 16 + 2));  // refined vertices of a level-2 cube: V - E + F = 2
  EXPECT_GT(mesh.positions.size(), normal_at.size());
  // The straight crease: 3 inner vertices on both sides of its seam, 2 ends shared by 3 faces' uvs each.
  EXPECT_EQ(on_crease, 2 * ((1 << level) - 1) + 2 * 3);
  // Catmull-Clark of a triangle cage at level 0 fans polygons and keeps unit normals.
  const ControlMesh tetra = import_control_mesh(test::source_dir() / "tests/data/tetrahedron.obj", {});
  const Mesh coarse = subdivide(tetra, {SubdivisionScheme::CatmullClark, 0});
  EXPECT_EQ(coarse.triangle_count(), 4u);
  for (const Vec3& n : coarse.normals) EXPECT_NEAR(length(n), 1.0f, 1e-5f);
}

TEST(Subdivision, ParsesOptions) {
  const nlohmann::json good = {{"scheme", "loop"}, {"level", 3}};
  const SubdivisionOptions options = parse_subdivision(JsonFields(good, "s.json: shapes[0].subdivision"));
  EXPECT_EQ(options.scheme, SubdivisionScheme::Loop);
  EXPECT_EQ(options.level, 3);
  const nlohmann::json defaults = nlohmann::json::object();
  EXPECT_EQ(parse_subdivision(JsonFields(defaults, "s.json: x")).level, 2);
  for (const nlohmann::json& bad : {nlohmann::json{{"scheme", "doo-sabin"}}, nlohmann::json{{"level", 9}},
                                    nlohmann::json{{"levels", 2}}}) {
    try {
      parse_subdivision(JsonFields(bad, "s.json: shapes[0].subdivision"));
      FAIL() << bad.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("s.json: shapes[0].subdivision"), std::string::npos) << e.what();
    }
  }
}

TEST(Subdivision, OpenGridTriangleCounts) {
  // A grid with a boundary (the cube above is closed): every quad gives 2 x 4^level triangles. The time of
  // level 5, a million triangles, is `ochre-bench --micro subdivision`.
  const ControlMesh plane = quad_grid_control_mesh(25, 20);  // 500 quads
  for (int level = 1; level <= 3; ++level)
    EXPECT_EQ(subdivide(plane, {SubdivisionScheme::CatmullClark, level}).triangle_count(), size_t(500 * 2)
                                                                                               << (2 * level))
        << "level " << level;
}

}  // namespace
}  // namespace ochre::subdivision_test
