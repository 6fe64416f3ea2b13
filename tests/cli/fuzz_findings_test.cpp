// Inputs that crashed, hung or misled ochre, found by fuzzing (tests/fuzz, docs/validation.md "Fuzzing"):
// each is now bad input, rejected by `ochre render` with exit code 2, a message naming the file and the
// field, and no output file. The same inputs are in tests/fuzz/corpus/, replayed by fuzz_corpus.*.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "support/test_paths.h"

namespace ochre::test::fuzz_findings_test {
namespace {

struct Rejection {
  std::filesystem::path dir;
  CommandResult result;
};

// Renders scene.json (with the extra files given) in a scratch directory.
Rejection render_scene(const std::string& scene,
                       const std::vector<std::pair<std::string, std::string>>& files = {}) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene);
  for (const auto& [name, text] : files) write_text(dir / name, text);
  return {dir, run_ochre("render scene.json -o out.exr", dir)};
}

void expect_rejected(const Rejection& r, const std::vector<std::string>& expected) {
  EXPECT_EQ(r.result.exit_code, 2) << r.result.output;
  for (const std::string& s : expected)
    EXPECT_NE(r.result.output.find(s), std::string::npos) << "message must contain '" << s << "'\n"
                                                          << r.result.output;
  EXPECT_FALSE(std::filesystem::exists(r.dir / "out.exr"));
}

std::string mesh_scene(const std::string& file, const std::string& options = "") {
  return fmt::format(R"({{"film": {{"resolution": [4, 4]}}, "integrator": {{"spp": 1}},
    "materials": {{"m": {{"type": "lambert"}}}},
    "shapes": [{{"type": "mesh", "file": "{}", "material": "m"{}}}]}})",
                     file, options);
}

const char* kSubdivided = R"(, "subdivision": {"level": 1})";

// Assimp 5.2's PLY reader looped forever on a header without end_header and on malformed header lines
// (fuzz_mesh): PLY headers are now checked line by line first.
TEST(FuzzFindings, PlyHeaderWithoutEndHeaderIsRejected) {
  const std::string truncated = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n";
  for (const std::string& options : {std::string(), std::string(kSubdivided)}) {
    SCOPED_TRACE(options);
    expect_rejected(render_scene(mesh_scene("mesh.ply", options), {{"mesh.ply", truncated}}),
                    {"scene.json", "shapes[0].file", "mesh.ply", "malformed PLY header: no end_header line"});
  }
  expect_rejected(render_scene(mesh_scene("magic_only.ply"), {{"magic_only.ply", "ply\r\n"}}),
                  {"magic_only.ply", "no end_header"});
  // The check goes by the content, not the name: Assimp picks its PLY reader by content too.
  expect_rejected(render_scene(mesh_scene("mesh.dat"), {{"mesh.dat", truncated}}),
                  {"mesh.dat", "end_header"});
}

std::string ply_triangle(int vertex_count, const std::string& face) {
  return fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n{}\n",
      vertex_count, face);
}

TEST(FuzzFindings, MalformedPlyHeaderLinesAreRejected) {
  const std::string start = "ply\nformat ascii 1.0\n";
  const std::string rest = "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const struct {
    std::string text, expected;
  } cases[] = {
      {"plyx\n" + vertex + face + rest, "the first line must be 'ply'"},
      {"ply\nformat ascii 1.0\xe4\xe4\n" + vertex + face + rest, "line 2: expected 'format ascii|binary"},
      {"ply\n" + vertex + face + rest, "line 2: expected the format line"},
      {start + start.substr(4) + vertex + face + rest, "line 3: a second format line"},
      {start + "propertty float w\n" + vertex + face + rest, "line 3: unknown keyword 'propertty'"},
      {start + "property float w\n" + vertex + face + rest, "line 3: a property before any element"},
      {start + "element vertex three\n" + face + rest, "line 3: expected 'element NAME COUNT'"},
      {start + vertex + "property flaot w\n" + face + rest, "line 7: expected 'property TYPE NAME'"},
      {start + vertex + "element face 1\nproperty list uchar vertex_indices\n" + rest,
       "line 8: expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    expect_rejected(render_scene(mesh_scene("mesh.ply"), {{"mesh.ply", c.text}}),
                    {"shapes[0].file", "mesh.ply: malformed PLY header: " + c.expected});
  }
  // The same file with a well-formed header renders.
  const Rejection good = render_scene(mesh_scene("mesh.ply"), {{"mesh.ply", start + vertex + face + rest}});
  EXPECT_EQ(good.result.exit_code, 0) << good.result.output;
}

// A PLY declaring 2 vertices and giving 3: the third vertex line is read as a face without vertices, on
// which Assimp's triangulation asserted (abort, fuzz_mesh).
TEST(FuzzFindings, PlyFaceWithoutVerticesIsRejected) {
  for (const std::string& options : {std::string(), std::string(kSubdivided)}) {
    SCOPED_TRACE(options);
    expect_rejected(render_scene(mesh_scene("mesh.ply", options), {{"mesh.ply", ply_triangle(2, "3 0 1 2")}}),
                    {"scene.json", "shapes[0].file", "mesh.ply", "face 0 has no vertices"});
  }
}

// Assimp's PLY reader passes vertex indices through unchecked; its post-processing then read past the
// vertex array (a render of garbage).
TEST(FuzzFindings, PlyVertexIndexOutOfRangeIsRejected) {
  for (const std::string& options : {std::string(), std::string(kSubdivided)}) {
    SCOPED_TRACE(options);
    expect_rejected(render_scene(mesh_scene("mesh.ply", options), {{"mesh.ply", ply_triangle(3, "3 0 1 7")}}),
                    {"mesh.ply", "face 0 uses vertex 7, but there are 3 vertices"});
  }
}

// A cube of quads; face_5 is the last face's vertex list.
std::string cube_obj(const std::string& face_5) {
  return "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf " +
         face_5 + "\n";
}

// scene.json: cube.obj subdivided, its face x = -1 towards the camera, lit from the side so that its shading
// shows the limit surface's normals.
void write_subdivided_cube_scene(const std::filesystem::path& dir) {
  write_text(dir / "scene.json", R"({"camera": {"eye": [-4, 2.5, 3]}, "film": {"resolution": [24, 24]},
    "integrator": {"spp": 2}, "materials": {"m": {"type": "lambert"}},
    "lights": [{"type": "point", "position": [-3, 4, -1], "intensity": 20}],
    "shapes": [{"type": "mesh", "file": "cube.obj", "material": "m", "subdivision": {"level": 2}}]})");
}

// Control-mesh faces with an edge of zero length (a vertex repeated, or two corners at the same position,
// welded into one) can make OpenSubdiv write outside its buffers: fuzz_mesh found a heap corruption (then a
// SEGV) and an assertion of Catmull-Clark's vertex masks under the sanitizers, on meshes combining several
// such faces (tests/fuzz/corpus/mesh/finding_*.obj), and in release builds such a face changed the refined
// surface. The repeated corner is now dropped before OpenSubdiv sees it, and a face left with fewer than 3
// corners goes with it: the surface must be the one without them, to the bit.
TEST(FuzzFindings, ZeroLengthEdgesOfAControlMeshAreDropped) {
  const auto dir = scratch_dir();
  write_subdivided_cube_scene(dir);
  write_text(dir / "cube.obj", cube_obj("4 1 5 8"));
  ASSERT_EQ(run_ochre("render scene.json -o clean.exr", dir).exit_code, 0);
  // The picture sees that face: the cube with a triangle there instead renders differently.
  write_text(dir / "cube.obj", cube_obj("4 1 5"));
  ASSERT_EQ(run_ochre("render scene.json -o triangle.exr", dir).exit_code, 0);
  ASSERT_FALSE(same_exr_pixels(dir / "clean.exr", dir / "triangle.exr"));
  // The same face with corner 1 given twice, with a vertex 9 at corner 8's position (welded to it), and
  // with two faces of no area after welding.
  write_text(dir / "cube.obj", cube_obj("4 1 1 5 8") + "f 1 1 2\n");
  const CommandResult repeated = run_ochre("render scene.json -o repeated.exr", dir);
  ASSERT_EQ(repeated.exit_code, 0) << repeated.output;
  EXPECT_TRUE(same_exr_pixels(dir / "clean.exr", dir / "repeated.exr"));
  write_text(dir / "cube.obj", cube_obj("4 1 5 9 8") + "v -1 1 1\nf 8 8 9\n");
  const CommandResult welded = run_ochre("render scene.json -o welded.exr", dir);
  ASSERT_EQ(welded.exit_code, 0) << welded.output;
  EXPECT_TRUE(same_exr_pixels(dir / "clean.exr", dir / "welded.exr"));
}

// A face given twice (from another corner, with either winding) made OpenSubdiv's limit evaluation corrupt
// memory on a non-manifold mesh (fuzz_mesh, tests/fuzz/corpus/mesh/finding_duplicate_faces.obj): duplicates
// are dropped, and the surface is the one without them.
TEST(FuzzFindings, DuplicateFacesOfAControlMeshAreDropped) {
  const auto dir = scratch_dir();
  write_subdivided_cube_scene(dir);
  write_text(dir / "cube.obj", cube_obj("4 1 5 8"));
  ASSERT_EQ(run_ochre("render scene.json -o clean.exr", dir).exit_code, 0);
  write_text(dir / "cube.obj", cube_obj("4 1 5 8") + "f 1 5 8 4\nf 8 5 1 4\nf 4 1 5 8\n");
  const CommandResult twice = run_ochre("render scene.json -o twice.exr", dir);
  ASSERT_EQ(twice.exit_code, 0) << twice.output;
  EXPECT_TRUE(same_exr_pixels(dir / "clean.exr", dir / "twice.exr"));
}

// A control mesh whose every face has fewer than 3 distinct vertices has nothing to refine.
TEST(FuzzFindings, AControlMeshOfDegenerateFacesOnlyIsRejected) {
  expect_rejected(
      render_scene(mesh_scene("flat.obj", kSubdivided),
                   {{"flat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 1 2\nf 3 3 3\n"}}),
      {"scene.json", "shapes[0].file", "flat.obj", "no polygons (faces of at least 3 distinct vertices)"});
}

// A face that passes through one vertex at two corners that are not neighbours (it touches itself) cannot be
// repaired without guessing the surface: it is refused.
TEST(FuzzFindings, AControlMeshFaceThatTouchesItselfIsRejected) {
  const std::string bowtie = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3 1 4 5\n";
  expect_rejected(
      render_scene(mesh_scene("bowtie.obj", kSubdivided), {{"bowtie.obj", bowtie}}),
      {"scene.json", "shapes[0].file", "bowtie.obj", "face 0", "passes through vertex 0 at (0, 0, 0) twice"});
}

// A spectrum file whose neighbouring values differ by more than the float range gave NaN at a knot
// (reported by fuzz_csv on an input written by hand).
TEST(FuzzFindings, SpectrumValuesBeyondTheFloatRangeAreRejected) {
  const std::string scene = R"({"film": {"resolution": [4, 4]}, "integrator": {"spp": 1},
    "materials": {"m": {"type": "lambert", "color": {"file": "huge.csv"}}},
    "shapes": [{"type": "plane", "material": "m"}]})";
  expect_rejected(
      render_scene(scene, {{"huge.csv", "wavelength,value\n400,0\n510,-3e38\n600,3e38\n"}}),
      {"scene.json", "'m'", "huge.csv", "values at index 1 and 2 differ by more than the float range"});
}

// "smooth_normals" and "flip_uv_v" were read without a type check: any other JSON type escaped as an
// internal error (exit 1). Found by reviewing the loader's unchecked reads; fuzz_scene reports it.
TEST(FuzzFindings, MeshOptionsMustBeBooleans) {
  for (const char* key : {"smooth_normals", "flip_uv_v"}) {
    for (const char* value : {"1", "\"yes\"", "null", "[true]"}) {
      SCOPED_TRACE(std::string(key) + ": " + value);
      expect_rejected(render_scene(mesh_scene("quad.obj", fmt::format(R"(, "{}": {})", key, value)),
                                   {{"quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}}),
                      {"scene.json", fmt::format("shapes[0].{}", key), "expected true or false"});
    }
  }
}

// A camera 9.2e18 units from the origin (fuzz_scene) made Embree abort on an invalid ray: its ray origins
// must stay within 1.8e18. Camera positions, orthographic sizes and vertices are held within +-1e15.
TEST(FuzzFindings, CoordinatesBeyondTheTracedRangeAreRejected) {
  const auto scene = [](const std::string& camera, const std::string& vertex) {
    return fmt::format(R"({{"camera": {}, "film": {{"resolution": [4, 4]}}, "integrator": {{"spp": 1}},
      "materials": {{"m": {{"type": "lambert"}}}},
      "shapes": [{{"type": "mesh", "file": "tri.obj", "material": "m"}}]}})",
                       camera, vertex);
  };
  const auto tri = [](const std::string& x) { return "v 0 0 0\nv " + x + " 0 0\nv 0 1 0\nf 1 2 3\n"; };
  const std::string ok_camera = R"({"eye": [0, 0, 5]})";
  expect_rejected(
      render_scene(scene(R"({"eye": [9223372036854775807, 1.45, 3.6], "target": [0, 1.4, 0]})", ""),
                   {{"tri.obj", tri("1")}}),
      {"scene.json", "camera.eye", "beyond +-1e15"});
  expect_rejected(
      render_scene(scene(R"({"transform": [{"translate": [0, -2e15, 0]}]})", ""), {{"tri.obj", tri("1")}}),
      {"scene.json", "camera.transform", "beyond +-1e15"});
  expect_rejected(render_scene(scene(R"({"type": "orthographic", "size": 1e20, "eye": [0, 0, 5]})", ""),
                               {{"tri.obj", tri("1")}}),
                  {"scene.json", "camera.size"});
  expect_rejected(render_scene(scene(ok_camera, ""), {{"tri.obj", tri("3e15")}}),
                  {"tri.obj", "position of vertex 1 lies beyond +-1e15"});
  // At the limit: rendered.
  const Rejection at_limit =
      render_scene(scene(R"({"eye": [1e15, 0, 5], "target": [0, 0, 0]})", ""), {{"tri.obj", tri("1e15")}});
  EXPECT_EQ(at_limit.result.exit_code, 0) << at_limit.result.output;
}

// A 50 MB name in a scene was echoed whole in the error (the audit's "expansion and echo" class): every
// program prints at most about 4 kB of a message, its beginning, its end and the count left out.
TEST(FuzzFindings, AHugeValueIsNotEchoedWhole) {
  const std::string huge(50'000'000, 'q');
  const Rejection r = render_scene(R"({"film": {"resolution": [4, 4]}, "integrator": {"spp": 1},
    "materials": {"m": {"type": ")" +
                                   huge + R"("}},
    "shapes": [{"type": "sphere", "radius": 1, "material": "m"}]})");
  expect_rejected(r, {"scene.json", "characters left out"});
  EXPECT_LT(r.result.output.size(), 10'000u);
}

}  // namespace
}  // namespace ochre::test::fuzz_findings_test
