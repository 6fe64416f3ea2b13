#include "renderer/shapes/subdivision.h"

#include <fmt/format.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cmath>
#include <memory>
#include <vector>

#include "renderer/util/load_progress.h"
#include "renderer/util/memory_budget.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

using namespace OpenSubdiv;

// Primvar buffers in the form Far::PrimvarRefiner expects (Clear + AddWithWeight).
struct Point3 {
  Vec3 v;
  void Clear() { v = {}; }
  void AddWithWeight(const Point3& source, float weight) { v += source.v * weight; }
};
struct Point2 {
  Vec2 v;
  void Clear() { v = {}; }
  void AddWithWeight(const Point2& source, float weight) {
    v.x += source.v.x * weight;
    v.y += source.v.y * weight;
  }
};

Sdc::SchemeType resolve_scheme(const ControlMesh& control, SubdivisionScheme scheme) {
  if (scheme == SubdivisionScheme::Auto)
    return control.all_triangles() ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  if (scheme == SubdivisionScheme::Loop) {
    if (!control.all_triangles())
      throw InputError(
          fmt::format("{}: Loop subdivision needs a control mesh of triangles only", control.name));
    return Sdc::SCHEME_LOOP;
  }
  return Sdc::SCHEME_CATMARK;
}

std::unique_ptr<Far::TopologyRefiner> make_refiner(const ControlMesh& control, Sdc::SchemeType scheme) {
  std::vector<int> crease_pairs;
  for (const auto& [a, b] : control.crease_edges) crease_pairs.insert(crease_pairs.end(), {a, b});
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(control.positions.size());
  desc.numFaces = static_cast<int>(control.face_sizes.size());
  desc.numVertsPerFace = control.face_sizes.data();
  desc.vertIndicesPerFace = control.face_vertices.data();
  desc.numCreases = static_cast<int>(control.crease_edges.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = control.crease_sharpness.data();
  desc.numCorners = static_cast<int>(control.corner_vertices.size());
  desc.cornerVertexIndices = control.corner_vertices.data();
  desc.cornerWeights = control.corner_sharpness.data();
  Far::TopologyDescriptor::FVarChannel uv_channel;
  if (!control.uvs.empty()) {
    uv_channel.numValues = static_cast<int>(control.uvs.size());
    uv_channel.valueIndices = control.face_uv_indices.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &uv_channel;
  }
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  sdc.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, sdc)));
  if (!refiner)
    throw InputError(fmt::format("{}: OpenSubdiv rejected the control mesh topology", control.name));
  return refiner;
}

// Refines a vertex (or face-varying) primvar from the control level to the last level.
template <typename Point, typename Refine>
std::vector<Point> refine(const Far::TopologyRefiner& refiner, std::vector<Point> values, Refine step) {
  for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
    std::vector<Point> next;
    step(level, values, next);
    values = std::move(next);
  }
  return values;
}

// Unit normals of the limit surface at the last-level vertices: the cross product of the limit
// tangents, oriented to the side where the adjacent refined faces are counter-clockwise (their
// area-weighted normal), which is also the fallback where the tangents degenerate.
std::vector<Vec3> limit_normals(const Far::PrimvarRefiner& primvar, const std::vector<Point3>& refined,
                                const Far::TopologyLevel& last) {
  std::vector<Point3> limit(refined.size()), du(refined.size()), dv(refined.size());
  primvar.Limit(refined, limit, du, dv);
  std::vector<Vec3> face_normals(refined.size());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    Vec3 n;  // Newell's method: twice the vector area of the polygon
    for (int k = 0; k < v.size(); ++k) n += cross(refined[v[k]].v, refined[v[(k + 1) % v.size()]].v);
    for (int k = 0; k < v.size(); ++k) face_normals[v[k]] += n;
  }
  std::vector<Vec3> normals(refined.size());
  for (size_t i = 0; i < refined.size(); ++i) {
    const Vec3 n = cross(du[i].v, dv[i].v);
    const float scale = std::max(dot(du[i].v, du[i].v), dot(dv[i].v, dv[i].v));
    if (dot(n, n) > 1e-12f * scale * scale) {
      normals[i] = face_forward(normalize(n), face_normals[i]);
    } else {
      normals[i] = dot(face_normals[i], face_normals[i]) > 0.0f ? normalize(face_normals[i]) : Vec3{0, 0, 1};
    }
  }
  return normals;
}

// Appends the triangles of polygon `corners` (output vertex indices, counter-clockwise). Quads are
// split along their shorter diagonal; other polygons are fanned.
void triangulate(const int* corners, int count, const std::vector<Vec3>& positions,
                 std::vector<uint32_t>& indices) {
  auto push = [&](int a, int b, int c) {
    indices.insert(indices.end(), {uint32_t(corners[a]), uint32_t(corners[b]), uint32_t(corners[c])});
  };
  if (count == 4) {
    const Vec3 d02 = positions[size_t(corners[2])] - positions[size_t(corners[0])];
    const Vec3 d13 = positions[size_t(corners[3])] - positions[size_t(corners[1])];
    if (dot(d02, d02) <= dot(d13, d13)) {
      push(0, 1, 2), push(0, 2, 3);
    } else {
      push(0, 1, 3), push(1, 2, 3);
    }
    return;
  }
  for (int k = 1; k + 1 < count; ++k) push(0, k, k + 1);
}

// Refusing before OpenSubdiv allocates: too much memory, or more vertices than 32-bit indices hold.
void check_refined_size(const ControlMesh& control, Sdc::SchemeType scheme, int level) {
  const double triangles = subdivided_triangle_count(control, scheme == Sdc::SCHEME_LOOP, level);
  const std::string what = fmt::format("{}: subdivision level {} of {} faces ({:.0f} triangles)",
                                       control.name, level, control.face_sizes.size(), triangles);
  // Vertices are fewer than triangles on a closed or open refined surface; 2^31 keeps int indices safe.
  check_triangle_estimate(triangles, kSubdividedTriangleBytes, what);
}

}  // namespace

double subdivided_triangle_count(const ControlMesh& control, bool loop, int level) {
  double corners = 0.0, fan_triangles = 0.0;
  for (int n : control.face_sizes) {
    corners += n;
    fan_triangles += n - 2;
  }
  if (level == 0) return fan_triangles;
  // Loop: every triangle becomes 4 per level. Catmull-Clark: an n-gon becomes n quads at level 1, every
  // quad 4 per later level, and each quad is output as 2 triangles.
  if (loop) return static_cast<double>(control.face_sizes.size()) * std::pow(4.0, level);
  return 2.0 * corners * std::pow(4.0, level - 1);
}

Mesh subdivide(const ControlMesh& control, const SubdivisionOptions& options) {
  control.validate(control.name);
  if (options.level < 0 || options.level > kMaxSubdivisionLevel)
    throw InputError(fmt::format("{}: subdivision level {} outside 0..{}", control.name, options.level,
                                 kMaxSubdivisionLevel));
  const Sdc::SchemeType scheme = resolve_scheme(control, options.scheme);
  check_refined_size(control, scheme, options.level);
  LoadProgress progress(fmt::format("subdividing {}", control.name));
  auto refiner = make_refiner(control, scheme);
  if (options.level > 0) {
    Far::TopologyRefiner::UniformOptions uniform(options.level);
    uniform.fullTopologyInLastLevel = true;  // PrimvarRefiner::Limit needs it
    refiner->RefineUniform(uniform);
  }
  progress.update(0.3);
  const Far::PrimvarRefiner primvar(*refiner);
  const Far::TopologyLevel& last = refiner->GetLevel(refiner->GetMaxLevel());

  std::vector<Point3> positions(control.positions.size());
  for (size_t i = 0; i < positions.size(); ++i) positions[i].v = control.positions[i];
  positions = refine(*refiner, std::move(positions), [&](int level, const auto& src, auto& dst) {
    dst.resize(size_t(refiner->GetLevel(level).GetNumVertices()));
    primvar.Interpolate(level, src, dst);
  });
  std::vector<Point3> colours(control.colours.size());
  for (size_t i = 0; i < colours.size(); ++i) colours[i].v = control.colours[i];
  if (!colours.empty()) {
    colours = refine(*refiner, std::move(colours), [&](int level, const auto& src, auto& dst) {
      dst.resize(size_t(refiner->GetLevel(level).GetNumVertices()));
      primvar.Interpolate(level, src, dst);
    });
  }
  std::vector<Point2> uvs(control.uvs.size());
  for (size_t i = 0; i < uvs.size(); ++i) uvs[i].v = control.uvs[i];
  const bool has_uvs = !uvs.empty();
  if (has_uvs) {
    uvs = refine(*refiner, std::move(uvs), [&](int level, const auto& src, auto& dst) {
      dst.resize(size_t(refiner->GetLevel(level).GetNumFVarValues(0)));
      primvar.InterpolateFaceVarying(level, src, dst, 0);
    });
  }
  progress.update(0.5);
  const std::vector<Vec3> normals = limit_normals(primvar, positions, last);
  progress.update(0.7);

  // Output vertices: one per refined vertex, or one per face-varying uv value when there are uvs
  // (a uv seam splits the vertices along it).
  const size_t output_count = has_uvs ? uvs.size() : positions.size();
  std::vector<int> vertex_of(output_count, 0);
  if (!has_uvs) {
    for (size_t i = 0; i < output_count; ++i) vertex_of[i] = int(i);
  }
  Mesh mesh;
  mesh.name = control.name;
  for (int f = 0; has_uvs && f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    const Far::ConstIndexArray values = last.GetFaceFVarValues(f, 0);
    for (int k = 0; k < v.size(); ++k) vertex_of[size_t(values[k])] = v[k];
  }
  mesh.positions.reserve(output_count + 1);  // + 1 spare position for Accel
  for (size_t i = 0; i < output_count; ++i) {
    const size_t source = size_t(vertex_of[i]);
    mesh.positions.push_back(positions[source].v);
    mesh.normals.push_back(normals[source]);
    if (!colours.empty()) mesh.colours.push_back(colours[source].v);
    if (has_uvs) mesh.uvs.push_back(uvs[i].v);
  }
  mesh.indices.reserve(size_t(last.GetNumFaces()) * 6);
  std::vector<int> corners;
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = has_uvs ? last.GetFaceFVarValues(f, 0) : last.GetFaceVertices(f);
    corners.assign(v.begin(), v.end());
    triangulate(corners.data(), int(corners.size()), mesh.positions, mesh.indices);
  }
  mesh.validate(control.name);
  progress.update(1.0);
  return mesh;
}

SubdivisionOptions parse_subdivision(const JsonFields& fields) {
  fields.check_known({"scheme", "level"});
  SubdivisionOptions options;
  const std::string scheme = fields.string("scheme", "auto");
  if (scheme == "auto") {
    options.scheme = SubdivisionScheme::Auto;
  } else if (scheme == "catmull-clark") {
    options.scheme = SubdivisionScheme::CatmullClark;
  } else if (scheme == "loop") {
    options.scheme = SubdivisionScheme::Loop;
  } else {
    fields.fail("scheme", fmt::format("unknown scheme '{}' (expected auto, catmull-clark or loop)", scheme));
  }
  options.level = static_cast<int>(fields.integer("level", options.level, 0, kMaxSubdivisionLevel));
  return options;
}

}  // namespace ochre
