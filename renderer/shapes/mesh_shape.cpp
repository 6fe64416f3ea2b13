// The "mesh" shape (docs/scene-format.md, "shapes"): a mesh file through Assimp, optionally refined by
// OpenSubdiv and displaced.
#include "renderer/shapes/mesh_shape.h"

#include "renderer/shapes/control_mesh.h"
#include "renderer/shapes/displacement.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/shapes/subdivision.h"

namespace ochre {

namespace {

Mesh load_triangles(const ShapeContext& ctx, const std::filesystem::path& path,
                    const MeshImportOptions& options) {
  if (ctx.fields.has("displacement"))
    ctx.fields.fail("displacement", "needs \"subdivision\" (displacement moves the refined vertices)");
  return ctx.fields.fields().in_context(
      "file", [&] { return import_mesh(path, ctx.to_world, options, &ctx.warnings); });
}

// Polygonal control mesh -> OpenSubdiv uniform refinement -> optional displacement along the smooth normal
// (shading normals recomputed).
Mesh load_subdivided(const ShapeContext& ctx, const std::filesystem::path& path) {
  const JsonFields& f = ctx.fields.fields();
  const SubdivisionOptions options =
      parse_subdivision(JsonFields(f.require("subdivision"), f.child("subdivision")));
  const ControlMesh control =
      f.in_context("file", [&] { return import_control_mesh(path, ctx.to_world, &ctx.warnings); });
  Mesh mesh = f.in_context("subdivision", [&] { return subdivide(control, options); });
  if (f.has("displacement")) {
    const DisplacementOptions d =
        parse_displacement(JsonFields(f.require("displacement"), f.child("displacement")), ctx.dir);
    f.in_context("displacement", [&] { displace(mesh, d, ctx.textures, ctx.origin); });
  }
  return mesh;
}

Mesh build_mesh(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const std::filesystem::path path = mesh_file(f, ctx.dir);
  const MeshImportOptions options = mesh_import_options(f);
  for (const char* key : {"flip_uv_v", "face_normals"})
    if (f.has("subdivision") && f.boolean(key))
      f.fail(key, "is not supported with \"subdivision\" (change the file instead)");
  return f.has("subdivision") ? load_subdivided(ctx, path) : load_triangles(ctx, path, options);
}

}  // namespace

std::filesystem::path mesh_file(const DeclaredFields& f, const std::filesystem::path& dir) {
  std::filesystem::path path = f.string("file");
  return path.is_relative() ? dir / path : path;
}

MeshImportOptions mesh_import_options(const DeclaredFields& f) {
  MeshImportOptions options;
  options.smooth_normals = f.boolean("smooth_normals");
  options.face_normals = f.boolean("face_normals");
  options.flip_uv_v = f.boolean("flip_uv_v");
  if (options.smooth_normals && options.face_normals)
    f.fail("face_normals", "contradicts \"smooth_normals\": give one of them");
  return options;
}

ShapeType mesh_shape() {
  return {
      "mesh",
      "any file Assimp reads: OBJ, PLY (vertex colours), glTF/GLB, ...; all meshes of the file are merged "
      "(one mesh per file material with `materials`); the file's normals, first UV set and first colour set "
      "are kept",
      {string_field("file", true, "the mesh file, relative to the file that names it"),
       boolean_field("smooth_normals", false, "compute smooth normals (the file's are replaced)"),
       boolean_field("face_normals", false,
                     "drop the file's normals: flat shading; not with `smooth_normals` or `subdivision`"),
       object_field("subdivision", "", "OpenSubdiv refinement of the file as a control mesh"),
       object_field("displacement", "", "displacement of the refined vertices (needs `subdivision`)"),
       object_field("materials", "",
                    "instead of `material`: the file's materials mapped to scene materials")},
      false,
      build_mesh};
}

}  // namespace ochre
