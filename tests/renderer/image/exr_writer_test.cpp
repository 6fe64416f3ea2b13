// EXR output and input: exact round trips of float channels with arbitrary names, string attributes and
// chromaticities; failures name the file and leave the previous file intact.

#include "renderer/image/exr_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "renderer/image/exr_reader.h"
#include "renderer/util/image_error.h"
#include "support/test_paths.h"

namespace ochre::exr_writer_test {
namespace {

namespace fs = std::filesystem;

// 3x2 pixels with values that a lossy or half path would not preserve.
ExrImage sample_image() {
  ExrImage image;
  image.width = 3;
  image.height = 2;
  auto channel = [](float base) {
    return std::vector<float>{base, -base, base * 1e-6f, base * 1e6f, 1.0f / 3.0f + base, 0.1f * base};
  };
  // Given order differs from the file's alphabetical order on purpose.
  image.channels = {{"R", channel(1.5f)},
                    {"G", channel(2.25f)},
                    {"B", channel(3.125f)},
                    {"albedo.R", channel(0.7f)},
                    {"S0.550,000000nm", channel(42.0f)}};
  image.string_attributes = {{"ochre:scene", "cornell.json"}, {"ochre:spp", "1024"}};
  image.chromaticities = acescg_chromaticities();
  return image;
}

size_t count_entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << text << "' does not contain '" << part << "'";
}

TEST(ExrWriter, FloatRoundTripIsExactForEveryChannelName) {
  const fs::path path = test::scratch_dir() / "image.exr";
  const ExrImage written = sample_image();
  write_exr(path, written);
  const ExrImage read = read_exr(path);
  EXPECT_EQ(read.width, 3);
  EXPECT_EQ(read.height, 2);
  ASSERT_EQ(read.channels.size(), written.channels.size());
  for (const auto& [name, values] : written.channels) {
    const std::vector<float>* back = read.find_channel(name);
    ASSERT_NE(back, nullptr) << name;
    EXPECT_EQ(*back, values) << name;
  }
  // The file stores channels sorted by name.
  EXPECT_EQ(read.channels[0].first, "B");
  EXPECT_EQ(read.channels[4].first, "albedo.R");
}

TEST(ExrWriter, StringAttributesAndChromaticitiesRoundTrip) {
  const fs::path path = test::scratch_dir() / "image.exr";
  write_exr(path, sample_image());
  const ExrImage read = read_exr(path);
  EXPECT_EQ(read.string_attributes.at("ochre:scene"), "cornell.json");
  EXPECT_EQ(read.string_attributes.at("ochre:spp"), "1024");
  ASSERT_TRUE(read.chromaticities.has_value());
  EXPECT_EQ(read.chromaticities->red, (std::array<float, 2>{0.713f, 0.293f}));
  EXPECT_EQ(read.chromaticities->green, (std::array<float, 2>{0.165f, 0.830f}));
  EXPECT_EQ(read.chromaticities->blue, (std::array<float, 2>{0.128f, 0.044f}));
  EXPECT_EQ(read.chromaticities->white, (std::array<float, 2>{0.32168f, 0.33767f}));

  ExrImage rec709 = sample_image();
  rec709.chromaticities = rec709_chromaticities();
  write_exr(path, rec709);
  EXPECT_EQ(read_exr(path).chromaticities->white, (std::array<float, 2>{0.3127f, 0.3290f}));

  rec709.chromaticities.reset();
  write_exr(path, rec709);
  EXPECT_FALSE(read_exr(path).chromaticities.has_value());
}

TEST(ExrWriter, LosslessCompressionsRoundTripExactly) {
  const fs::path dir = test::scratch_dir();
  for (const char* name : {"none", "rle", "zips", "zip", "piz"}) {
    const fs::path path = dir / (std::string(name) + ".exr");
    write_exr(path, sample_image(), parse_exr_compression(name));
    EXPECT_EQ(*read_exr(path).find_channel("R"), *sample_image().find_channel("R")) << name;
  }
  EXPECT_THROW(parse_exr_compression("zipp"), ImageError);
}

TEST(ExrWriter, HalfChannelsRoundToHalfPrecision) {
  const fs::path path = test::scratch_dir() / "half.exr";
  ExrImage image;
  image.width = 4;
  image.height = 1;
  image.channels = {{"Y", {0.5f, 1.0f / 3.0f, 65504.0f, 1e6f}}};
  write_exr(path, image, ExrCompression::zip, /*half=*/true);
  const ExrImage read = read_exr(path);
  const std::vector<float>& back = *read.find_channel("Y");
  EXPECT_EQ(back[0], 0.5f);                                    // exactly representable
  EXPECT_EQ(back[1], 0.333251953125f);                         // nearest half to 1/3 (10-bit mantissa)
  EXPECT_EQ(back[2], 65504.0f);                                // largest half
  EXPECT_EQ(back[3], std::numeric_limits<float>::infinity());  // beyond the half range
}

TEST(ExrWriter, MissingDirectoryThrowsNamingTheFileAndLeavesNothing) {
  const fs::path dir = test::scratch_dir();
  const fs::path path = dir / "missing" / "image.exr";
  try {
    write_exr(path, sample_image());
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), path.string());
  }
  EXPECT_EQ(count_entries(dir), 0u);
}

TEST(ExrWriter, FailedWriteKeepsThePreviousFile) {
  const fs::path dir = test::scratch_dir();
  const fs::path path = dir / "image.exr";
  write_exr(path, sample_image());

  ExrImage wrong_size = sample_image();
  wrong_size.channels[1].second.pop_back();
  try {
    write_exr(path, wrong_size);
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), path.string());
    expect_contains(error.what(), "'G'");
  }
  ExrImage reserved = sample_image();
  reserved.string_attributes["compression"] = "none";
  EXPECT_THROW(write_exr(path, reserved), ImageError);
  ExrImage duplicate = sample_image();
  duplicate.channels.push_back(duplicate.channels[0]);
  EXPECT_THROW(write_exr(path, duplicate), ImageError);

  EXPECT_EQ(*read_exr(path).find_channel("R"), *sample_image().find_channel("R"));
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(ExrReader, MissingOrInvalidFilesAreNamed) {
  const fs::path dir = test::scratch_dir();
  try {
    read_exr(dir / "nothing.exr");
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), (dir / "nothing.exr").string());
  }
  std::ofstream(dir / "text.exr") << "not an image";
  try {
    read_exr(dir / "text.exr");
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), (dir / "text.exr").string());
  }
}

}  // namespace
}  // namespace ochre::exr_writer_test
