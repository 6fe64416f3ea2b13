#pragma once
// Subdivision surfaces through OpenSubdiv (Far::TopologyRefiner, uniform refinement): turns a
// polygonal ControlMesh into a triangle Mesh with smooth limit-surface normals.

#include "renderer/geometry/mesh.h"
#include "renderer/json/json_fields.h"
#include "renderer/shapes/control_mesh.h"

namespace ochre {

// Auto: Loop when every control face is a triangle, Catmull-Clark otherwise.
enum class SubdivisionScheme { Auto, CatmullClark, Loop };

struct SubdivisionOptions {
  SubdivisionScheme scheme = SubdivisionScheme::Auto;
  int level = 2;  // uniform refinement steps, 0..8
};

inline constexpr int kMaxSubdivisionLevel = 8;

// Uniformly refines `control` `options.level` times and triangulates the result.
// - Positions are refined with vertex interpolation (the refined points, not their limit), colours
//   with vertex interpolation, uvs through a face-varying channel (corners of the uv boundary stay
//   sharp, FVAR_LINEAR_CORNERS_ONLY; seams split the output vertices, positions stay identical).
// - Boundary edges and corners are interpolated (VTX_BOUNDARY_EDGE_AND_CORNER); crease edges and
//   corner vertices of the control mesh are applied (sharpness >= 10 is infinitely sharp).
// - Normals are those of the LIMIT surface at each refined vertex (cross product of the limit
//   tangents), so shading is smooth at any level; they point to the side from which the control
//   faces are counter-clockwise. Catmull-Clark quads are split into two triangles (faces x 4^level
//   x 2 triangles for quad meshes); Loop yields faces x 4^level triangles; at level 0 n-gons are
//   fan-triangulated (and Catmull-Clark limit normals of non-quad faces are approximate).
// - Loop needs an all-triangle control mesh; Catmull-Clark accepts any polygons.
// Throws InputError starting with control.name when the mesh is invalid, the level is out of range,
// Loop is asked for a mesh with non-triangles, or OpenSubdiv rejects the topology.
// Before OpenSubdiv allocates anything, the refined size is estimated (subdivided_triangle_count) and
// refused with InputError when it exceeds the memory limit (renderer/util/memory_budget.h) or 2^31
// triangles; a long subdivision reports its progress (renderer/util/load_progress.h).
Mesh subdivide(const ControlMesh& control, const SubdivisionOptions& options);

// Triangles of `control` refined `level` times with Loop (loop = true) or Catmull-Clark.
double subdivided_triangle_count(const ControlMesh& control, bool loop, int level);

// {"scheme": "auto" | "catmull-clark" | "loop", "level": 0..8}; unknown members are errors.
SubdivisionOptions parse_subdivision(const JsonFields& fields);

}  // namespace ochre
