// The image library module (renderer/image/image_library.h) through its interface: what it reads back of a
// PNG it wrote (header, exact 8-bit codes, floats scaled to [0, 1]), and a file replaced between the header
// and the pixels is refused rather than read into a buffer of the old size.

#include "renderer/image/image_library.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace ochre::test::image_library_test {
namespace {

namespace fs = std::filesystem;

// A w x h RGB PNG whose codes are (7 i) mod 256 for value i.
std::vector<std::uint8_t> write_codes(const fs::path& file, int width, int height) {
  std::vector<std::uint8_t> codes(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = static_cast<std::uint8_t>(7 * i);
  image_library().write_uint8("png", file.string(), width, height, 3, codes.data(), {{"Software", "test"}});
  return codes;
}

TEST(ImageLibrary, ReadsBackThePngItWrote) {
  const fs::path file = scratch_dir() / "codes.png";
  const std::vector<std::uint8_t> codes = write_codes(file, 5, 3);
  ASSERT_TRUE(image_library_loaded());

  const ImageHeader header = image_library().read_header(file.string());
  EXPECT_EQ(header.width, 5);
  EXPECT_EQ(header.height, 3);
  EXPECT_EQ(header.channels, 3);
  EXPECT_EQ(header.pixel_type, "uint8");
  EXPECT_FALSE(header.floating_point);
  EXPECT_FALSE(header.mipmapped());
  ASSERT_EQ(header.levels.size(), 1u);
  EXPECT_EQ(header.levels[0].width, 5);

  EXPECT_EQ(image_library().read_uint8(file.string(), {5, 3, 3}), codes);
  const std::vector<float> values = image_library().read_float(file.string(), 0, {5, 3, 3});
  ASSERT_EQ(values.size(), codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i) EXPECT_FLOAT_EQ(values[i], codes[i] / 255.0f) << i;
  // Fewer channels than the file has: the first ones, pixel by pixel.
  const std::vector<float> red = image_library().read_float(file.string(), 0, {5, 3, 1});
  ASSERT_EQ(red.size(), 15u);
  EXPECT_FLOAT_EQ(red[1], codes[3] / 255.0f);
}

TEST(ImageLibrary, AFileReplacedAfterItsHeaderIsRefused) {
  const fs::path file = scratch_dir() / "replaced.png";
  write_codes(file, 4, 4);
  const ImageHeader header = image_library().read_header(file.string());
  write_codes(file, 2, 2);  // another image under the same name
  const ImageLevelSize size{header.width, header.height, header.channels};
  try {
    (void)image_library().read_float(file.string(), 0, size);
    FAIL() << "read a 2x2 file as 4x4";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("changed while it was read"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)image_library().read_uint8(file.string(), size), std::runtime_error);
}

TEST(ImageLibrary, UnreadableFilesThrowWithTheLibrarysMessage) {
  const fs::path file = scratch_dir() / "not-an-image.png";
  { std::ofstream(file) << "plain text"; }
  EXPECT_THROW((void)image_library().read_header(file.string()), std::runtime_error);
  EXPECT_THROW((void)image_library().read_header((scratch_dir() / "missing.exr").string()),
               std::runtime_error);
}

}  // namespace
}  // namespace ochre::test::image_library_test
