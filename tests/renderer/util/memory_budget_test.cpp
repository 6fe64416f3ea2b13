// Memory estimates (renderer/util/memory_budget.h) refuse what does not fit before allocating it: the film,
// subdivided and tessellated meshes, procedural shapes.

#include "renderer/util/memory_budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/film/film.h"
#include "renderer/output/render_output.h"
#include "renderer/shapes/groove_shapes.h"
#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/subdivision.h"
#include "spectra/byte_size.h"
#include "spectra/input_error.h"
#include "support/input_error_of.h"

namespace ochre::memory_budget_test {
namespace {

// Restores the default limit when a test ends.
struct ScopedMemoryLimit {
  explicit ScopedMemoryLimit(std::optional<std::uint64_t> bytes) { set_memory_limit(bytes); }
  ~ScopedMemoryLimit() { set_memory_limit(std::nullopt); }
};

using test::input_error_of;

TEST(MemoryBudget, DefaultLimitIsTheMachinesMemory) {
  EXPECT_GT(machine_memory_bytes(), 64 * kMiB);
  EXPECT_EQ(memory_limit(), machine_memory_bytes());
  const ScopedMemoryLimit limit(512 * kMiB);
  EXPECT_EQ(memory_limit(), 512 * kMiB);
}

TEST(MemoryBudget, EstimateAboveTheLimitNamesBothFigures) {
  const ScopedMemoryLimit limit(1 * kMiB);
  EXPECT_EQ(input_error_of([] { check_memory_estimate(1.5 * kMiB, "a thing"); }),
            "a thing needs 1.5 MiB; the memory limit (--memory-limit) is 1 MiB");
  EXPECT_EQ(input_error_of([] { check_memory_estimate(1.0 * kMiB, "a thing"); }), "");
}

TEST(MemoryBudget, HugeFilmIsRefusedBeforeAllocation) {
  const std::string message = input_error_of([] { Film film(65536, 65536); });
  EXPECT_EQ(message.rfind("film 65536x65536 (XYZ) needs 320 GiB; this machine has ", 0), 0u) << message;
  EXPECT_NE(message.find("(use --memory-limit to change the limit)"), std::string::npos);
}

TEST(MemoryBudget, RenderEstimateCountsEveryLayerAndOutput) {
  OutputSettings outputs;
  outputs.exr = "out.exr";
  outputs.png = "out.png";
  outputs.aovs = true;
  outputs.stokes = true;
  outputs.spectral_bins = 16;
  // Per pixel: XYZ 80 + AOVs 128 + Stokes 144 + 16 bins x 4 components x 16 = 1376 bytes of film; RGB 12;
  // the EXR's 3 + 8 + 14 + 64 float channels = 356 bytes.
  EXPECT_EQ(Film::bytes_per_pixel(film_layers(outputs)), 1376u);
  const ScopedMemoryLimit limit(1744 * 100 - 1);
  EXPECT_EQ(input_error_of([&] { check_render_memory(10, 10, outputs); }),
            "film 10x10 (XYZ, AOVs, Stokes, 16 spectral bins) with its output buffers needs 170 KiB; the "
            "memory limit (--memory-limit) is 170 KiB");
  set_memory_limit(1744 * 100);
  EXPECT_EQ(input_error_of([&] { check_render_memory(10, 10, outputs); }), "");
}

TEST(MemoryBudget, SubdivisionTriangleCountsPerScheme) {
  ControlMesh control;
  control.face_sizes = {4, 4, 3};
  EXPECT_EQ(subdivided_triangle_count(control, false, 0), 5.0);                 // fans
  EXPECT_EQ(subdivided_triangle_count(control, false, 1), 2.0 * 11);            // n quads per n-gon
  EXPECT_EQ(subdivided_triangle_count(control, false, 8), 2.0 * 11 * 16384.0);  // x 4 per level after
  control.face_sizes = {3, 3};
  EXPECT_EQ(subdivided_triangle_count(control, true, 8), 2.0 * 65536.0);
}

TEST(MemoryBudget, SubdivisionThatWouldExplodeIsRefusedWithTheEstimate) {
  ControlMesh control;
  control.name = "slab";
  control.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  control.face_sizes = {4};
  control.face_vertices = {0, 1, 2, 3};
  const ScopedMemoryLimit limit(1 * kMiB);
  SubdivisionOptions options;
  options.scheme = SubdivisionScheme::CatmullClark;
  options.level = 6;  // 8192 triangles x 300 bytes
  EXPECT_EQ(input_error_of([&] { subdivide(control, options); }),
            "slab: subdivision level 6 of 1 faces (8192 triangles) needs 2.3 MiB; the memory limit "
            "(--memory-limit) is 1 MiB");
  options.level = 5;
  EXPECT_EQ(subdivide(control, options).triangle_count(), 2048u);
}

TEST(MemoryBudget, SphereEstimateCountsItsTriangles) {
  EXPECT_EQ(sphere_triangle_count(24), static_cast<double>(make_sphere(1.0f, 24).triangle_count()));
  EXPECT_EQ(sphere_memory_bytes(4096), sphere_triangle_count(4096) * kTessellatedTriangleBytes);
}

TEST(MemoryBudget, GrooveShapeEstimatesCountTheirTriangles) {
  const GroovePlate plate{60, 0.5f, 7, 3};
  EXPECT_EQ(groove_plate_triangle_count(plate),
            static_cast<double>(make_groove_plate(plate).triangle_count()));
  const GroovePlate tiled{60, 0.5f, 7, 30};  // 30 / (8 x 0.5) = 7.5: 8 tiles along the grooves
  EXPECT_EQ(groove_plate_tiles(tiled), 8.0);
  EXPECT_EQ(groove_plate_triangle_count(tiled), 4.0 * 7 * 8);
  EXPECT_EQ(groove_plate_triangle_count(tiled),
            static_cast<double>(make_groove_plate(tiled).triangle_count()));
  EXPECT_EQ(cylinder_triangle_count(13), static_cast<double>(make_cylinder(1, 2, 13).triangle_count()));
  GroovedCylinder cylinder{1, 1, 90, 0.3f, 11};  // floor(1 / 0.3) = 3 grooves
  EXPECT_EQ(groove_count(cylinder), 3.0);
  EXPECT_EQ(grooved_cylinder_triangle_count(cylinder),
            static_cast<double>(make_grooved_cylinder(cylinder).triangle_count()));
  cylinder.pitch = 2;  // wider than the height: one groove
  EXPECT_EQ(groove_count(cylinder), 1.0);
  cylinder.height = 1e30f, cylinder.pitch = 1e-30f;  // far beyond int: counted, never converted
  EXPECT_EQ(grooved_cylinder_triangle_count(cylinder), 4.0 * std::floor(double(1e30f) / double(1e-30f)) * 11);
}

TEST(MemoryBudget, TriangleEstimateRefusesMoreThanThirtyTwoBitIndicesWhateverTheLimit) {
  const ScopedMemoryLimit limit(std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(input_error_of([] { check_triangle_estimate(2147483647.0, 1.0, "tube"); }), "");
  EXPECT_EQ(input_error_of([] { check_triangle_estimate(2147483648.0, 1.0, "tube"); }),
            "tube: more than 2^31 triangles, beyond the renderer's 32-bit indices");
  set_memory_limit(kMiB);
  EXPECT_EQ(input_error_of([] { check_triangle_estimate(8192.0, 150.0, "tube"); }),
            "tube needs 1.2 MiB; the memory limit (--memory-limit) is 1 MiB");
}

}  // namespace
}  // namespace ochre::memory_budget_test
