// Every reader of user files refuses what is not a regular file (spectra/input_file.h) before any
// library opens it, so a FIFO never hangs the renderer and a device is never read: meshes (and the
// files a mesh names), EXR and PNG images, textures, environment maps and OCIO configs.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

#include "renderer/image/display_image.h"
#include "renderer/image/exr_reader.h"
#include "renderer/lights/environment_map.h"
#include "renderer/shapes/control_mesh.h"
#include "renderer/shapes/mesh_file_reader.h"
#include "renderer/shapes/mesh_import.h"
#include "renderer/texture/texture_system.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::input_readers_test {
namespace {

namespace fs = std::filesystem;

// The message of the std::exception thrown by f (empty when nothing is thrown).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

fs::path make_fifo(const fs::path& path) {
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

TEST(InputReaders, MeshThatIsAFifoOrADeviceIsRefused) {
  const fs::path fifo = make_fifo(test::scratch_dir() / "mesh.obj");
  const std::string message = error_of([&] { import_mesh(fifo, Transform::identity()); });
  EXPECT_EQ(message, fifo.string() + ": the mesh file is a FIFO, not a regular file");
  EXPECT_EQ(error_of([&] { import_control_mesh(fifo, Transform::identity()); }), message);
  EXPECT_EQ(error_of([] { import_mesh("/dev/zero", Transform::identity()); }),
            "/dev/zero: the mesh file is a character device, not a regular file");
}

TEST(InputReaders, FileNamedByAMeshThatIsAFifoIsRefused) {
  // The OBJ is fine; its material library is a FIFO that Assimp would block on.
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "tri.obj") << "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  make_fifo(dir / "lib.mtl");
  const std::string expected = (dir / "lib.mtl").string() + ": the mesh file is a FIFO, not a regular file";
  EXPECT_EQ(error_of([&] { import_mesh(dir / "tri.obj", Transform::identity()); }), expected);
  EXPECT_EQ(error_of([&] { import_control_mesh(dir / "tri.obj", Transform::identity()); }), expected);
}

TEST(InputReaders, MissingMaterialLibraryIsStillOnlyAWarning) {
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "tri.obj") << "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(import_mesh(dir / "tri.obj", Transform::identity()).triangle_count(), 1u);
}

// One convex polygon of n vertices on the unit circle.
fs::path polygon_obj(const fs::path& dir, int n) {
  const fs::path file = dir / ("polygon" + std::to_string(n) + ".obj");
  std::ofstream out(file);
  for (int i = 0; i < n; ++i)
    out << "v " << std::cos(2 * M_PI * i / n) << " " << std::sin(2 * M_PI * i / n) << " 0\n";
  out << "f";
  for (int i = 1; i <= n; ++i) out << " " << i;
  out << "\n";
  return file;
}

TEST(InputReaders, PolygonTooLargeToTriangulateIsRefusedAtOnce) {
  const fs::path file = polygon_obj(test::scratch_dir(), 40000);  // minutes of ear clipping
  const auto start = std::chrono::steady_clock::now();
  const std::string message = error_of([&] { import_mesh(file, Transform::identity()); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_TRUE(contains(message, file.string() + ": polygons too large to triangulate")) << message;
  EXPECT_TRUE(contains(message, "has 40000 vertices")) << message;
  // A control mesh for subdivision takes it: OpenSubdiv needs no triangulation.
  EXPECT_EQ(import_control_mesh(file, Transform::identity()).face_sizes.front(), 40000);
}

TEST(InputReaders, PolygonOfAThousandVerticesIsTriangulated) {
  const fs::path file = polygon_obj(test::scratch_dir(), 1000);
  EXPECT_EQ(import_mesh(file, Transform::identity()).triangle_count(), 998u);
}

TEST(InputReaders, ExrThatIsAFifoOrADeviceIsRefused) {
  const fs::path fifo = make_fifo(test::scratch_dir() / "image.exr");
  EXPECT_EQ(error_of([&] { read_exr(fifo); }),
            fifo.string() + ": the image file is a FIFO, not a regular file");
  EXPECT_EQ(error_of([] { read_exr("/dev/zero"); }),
            "/dev/zero: the image file is a character device, not a regular file");
}

TEST(InputReaders, ExrIsReadThroughItsDescriptor) {
  const fs::path file = test::scratch_dir() / "small.exr";
  ExrImage image;
  image.width = 2;
  image.height = 1;
  image.channels = {{"R", {1, 2}}, {"G", {3, 4}}, {"B", {5, 6}}};
  write_exr(file, image);
  const ExrImage back = read_exr(file);
  ASSERT_EQ(back.channels.size(), 3u);
  EXPECT_EQ(*back.find_channel("G"), (std::vector<float>{3, 4}));
}

TEST(InputReaders, PngThatIsAFifoIsRefused) {
  const fs::path fifo = make_fifo(test::scratch_dir() / "image.png");
  int w = 0, h = 0;
  EXPECT_EQ(error_of([&] { read_png_rgb8(fifo, w, h); }),
            fifo.string() + ": the image file is a FIFO, not a regular file");
}

TEST(InputReaders, TextureThatIsAFifoOrADeviceIsRefused) {
  const fs::path dir = test::scratch_dir();
  const fs::path fifo = make_fifo(dir / "albedo.png");
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  EXPECT_EQ(error_of([&] { textures.add_texture(fifo, "auto", channels); }),
            fifo.string() + ": the texture is a FIFO, not a regular file");
  EXPECT_EQ(error_of([&] { textures.add_texture("/dev/zero", "auto", channels); }),
            "/dev/zero: the texture is a character device, not a regular file");
}

TEST(InputReaders, EnvironmentMapThatIsAFifoIsRefused) {
  const fs::path fifo = make_fifo(test::scratch_dir() / "sky.hdr");
  EXPECT_EQ(error_of([&] { EnvironmentMap::load(fifo); }),
            fifo.string() + ": the environment map is a FIFO, not a regular file");
}

TEST(InputReaders, OcioConfigThatIsAFifoIsRefused) {
  const fs::path fifo = make_fifo(test::scratch_dir() / "config.ocio");
  DisplayOptions options;
  options.ocio_config = fifo.string();
  const std::string message = error_of([&] { to_display_rgb8(1, 1, {0.5f, 0.5f, 0.5f}, options); });
  EXPECT_EQ(message, fifo.string() + ": the OCIO config is a FIFO, not a regular file");
}

}  // namespace
}  // namespace ochre::input_readers_test
