// OiioTextureProvider: sRGB decoding before filtering, exact texel values, uv orientation (v up),
// MIP filtering, channel rules, errors, the conversion cache and concurrent lookups. Test images are
// written at test time: 8-bit sRGB PNGs with the display-image writer, linear EXRs with the EXR writer,
// 8-bit grey as binary PGM (a 12-byte header, written here).

#include "renderer/texture/texture_system.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"
#include "spectra/color_space.h"
#include "support/test_paths.h"

namespace ochre::texture_system_test {
namespace {

namespace fs = std::filesystem;

// Linear value whose 8-bit sRGB encoding is `code`, so write_display_png stores exactly `code`.
float linear_for_code(int code) {
  return srgb_decode(static_cast<float>(code) / 255.0f);
}

// 8-bit sRGB PNG whose pixels hold the given code values (3 per pixel, row 0 = top).
fs::path write_png_codes(const fs::path& path, int width, int height, const std::vector<int>& codes) {
  std::vector<float> linear;
  for (int code : codes) linear.push_back(linear_for_code(code));
  DisplayOptions options;
  options.ocio_config = "none";  // plain sRGB transfer: the stored codes are exactly `codes`
  write_display_png(path, width, height, linear, options);
  int w = 0, h = 0;
  const std::vector<std::uint8_t> stored = read_png_rgb8(path, w, h);
  EXPECT_EQ(std::vector<int>(stored.begin(), stored.end()), codes) << "test image set-up";
  return path;
}

// Linear float RGB EXR (3 values per pixel, row 0 = top).
fs::path write_exr_rgb(const fs::path& path, int width, int height, const std::vector<float>& rgb) {
  ExrImage image;
  image.width = width;
  image.height = height;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    std::vector<float> plane;
    for (std::size_t i = static_cast<std::size_t>(c); i < rgb.size(); i += 3) plane.push_back(rgb[i]);
    image.channels.emplace_back(names[c], std::move(plane));
  }
  write_exr(path, image);
  return path;
}

// 8-bit grey binary PGM (Netpbm P5), read by OIIO as a 1-channel UINT8 image.
fs::path write_pgm(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& codes) {
  std::ofstream file(path, std::ios::binary);
  file << "P5\n" << width << " " << height << "\n255\n";
  file.write(reinterpret_cast<const char*>(codes.data()), static_cast<std::streamsize>(codes.size()));
  return path;
}

std::array<float, 3> rgb_at(const OiioTextureProvider& textures, int id, float u, float v, float footprint) {
  std::array<float, 3> out{};
  textures.lookup(id, Vec2{u, v}, footprint, 0, 3, out.data());
  return out;
}

// Sets (or, with nullopt, unsets) an environment variable for the lifetime of the object.
class EnvOverride {
 public:
  EnvOverride(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      ::setenv(name, value->c_str(), 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~EnvOverride() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// 2x2 image with four distinct colours: top-left red, top-right green, bottom-left blue, bottom-right grey.
const std::vector<float> kQuadrants = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};

TEST(TextureSystem, Srgb8BitCodeDecodesToLinear) {
  const fs::path dir = test::scratch_dir();
  const fs::path png = write_png_codes(dir / "grey188.png", 4, 4, std::vector<int>(48, 188));
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(png, "auto", channels);
  EXPECT_EQ(channels, 3);
  // 188/255 = 0.73725 encoded -> ((0.73725 + 0.055) / 1.055)^2.4 = 0.50289 linear.
  for (float footprint : {0.0f, 0.3f, 1.0f}) {
    for (float value : rgb_at(textures, id, 0.3f, 0.6f, footprint)) EXPECT_NEAR(value, 0.5029f, 0.003f);
  }
  // "linear" takes the codes as they are.
  const int raw = textures.add_texture(png, "linear", channels);
  EXPECT_NE(raw, id);
  for (float value : rgb_at(textures, raw, 0.3f, 0.6f, 0.0f)) EXPECT_NEAR(value, 188.0f / 255.0f, 0.001f);
}

TEST(TextureSystem, SrgbIsDecodedBeforeFiltering) {
  // Checker of codes 188 (linear 0.5029) and 0: the filtered average of the decoded texels is 0.2514.
  // Decoding the filtered code (94) instead would give 0.112, and not decoding at all 0.369.
  const fs::path dir = test::scratch_dir();
  const fs::path png =
      write_png_codes(dir / "checker.png", 2, 2, {188, 188, 188, 0, 0, 0, 0, 0, 0, 188, 188, 188});
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(png, "srgb", channels);
  for (float value : rgb_at(textures, id, 0.3f, 0.8f, 1.0f)) EXPECT_NEAR(value, 0.5029f / 2.0f, 0.003f);
  for (float value : rgb_at(textures, id, 0.25f, 0.75f, 0.0f)) EXPECT_NEAR(value, 0.5029f, 0.003f);
  for (float value : rgb_at(textures, id, 0.75f, 0.75f, 0.0f)) EXPECT_EQ(value, 0.0f);
}

TEST(TextureSystem, LinearExrIsReturnedUnchanged) {
  const fs::path dir = test::scratch_dir();
  const std::vector<float> pixel = {0.18f, 2.5f, 0.0031308f};
  std::vector<float> rgb;
  for (int i = 0; i < 16; ++i) rgb.insert(rgb.end(), pixel.begin(), pixel.end());
  const fs::path exr = write_exr_rgb(dir / "linear.exr", 4, 4, rgb);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(exr, "auto", channels);
  EXPECT_EQ(channels, 3);
  for (float footprint : {0.0f, 0.5f}) {
    const auto value = rgb_at(textures, id, 0.4f, 0.9f, footprint);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(value[c], pixel[c]);
  }
}

TEST(TextureSystem, TexelCentresAreExactAndVPointsUp) {
  const fs::path dir = test::scratch_dir();
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(exr, "linear", channels);
  // v = 0 is the bottom row of the image: uv (0.25, 0.75) is the top-left texel.
  const std::array<std::array<float, 2>, 4> centres = {
      {{0.25f, 0.75f}, {0.75f, 0.75f}, {0.25f, 0.25f}, {0.75f, 0.25f}}};
  for (std::size_t texel = 0; texel < 4; ++texel) {
    const auto value = rgb_at(textures, id, centres[texel][0], centres[texel][1], 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(value[c], kQuadrants[texel * 3 + c]) << "texel " << texel;
  }
  // Periodic wrap: (1.25, -0.25) is the same point as (0.25, 0.75).
  const auto wrapped = rgb_at(textures, id, 1.25f, -0.25f, 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(wrapped[c], kQuadrants[static_cast<std::size_t>(c)]);
}

TEST(TextureSystem, LargeFootprintReturnsImageAverage) {
  const fs::path dir = test::scratch_dir();
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(exr, "linear", channels);
  const float expected = (1.0f + 0.5f) / 4.0f;  // every channel: one 1 and one 0.5 among 4 texels
  for (auto uv : {Vec2{0.25f, 0.75f}, Vec2{0.6f, 0.1f}}) {
    for (float value : rgb_at(textures, id, uv.x, uv.y, 1.0f)) EXPECT_NEAR(value, expected, 1e-4f);
  }
}

TEST(TextureSystem, ChannelRules) {
  const fs::path dir = test::scratch_dir();
  const fs::path pgm = write_pgm(dir / "grey.pgm", 2, 2, {188, 188, 188, 188});
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int grey = textures.add_texture(pgm, "auto", channels);
  EXPECT_EQ(channels, 1);
  for (float value : rgb_at(textures, grey, 0.5f, 0.5f, 0.0f)) EXPECT_NEAR(value, 0.5029f, 0.003f);
  float beyond[3] = {-1, -1, -1};
  textures.lookup(grey, Vec2{0.5f, 0.5f}, 0.0f, 1, 3, beyond);
  for (float value : beyond) EXPECT_EQ(value, 0.0f);

  const int rgb = textures.add_texture(exr, "linear", channels);
  EXPECT_EQ(channels, 3);
  float blue_on[3] = {-1, -1, -1};
  textures.lookup(rgb, Vec2{0.25f, 0.25f}, 0.0f, 2, 3, blue_on);  // bottom-left texel is blue
  EXPECT_FLOAT_EQ(blue_on[0], 1.0f);
  EXPECT_EQ(blue_on[1], 0.0f);
  EXPECT_EQ(blue_on[2], 0.0f);
  float green = -1;
  textures.lookup(rgb, Vec2{0.75f, 0.75f}, 0.0f, 1, 1, &green);  // top-right texel is green
  EXPECT_FLOAT_EQ(green, 1.0f);
  EXPECT_THROW(textures.lookup(7, Vec2{}, 0.0f, 0, 1, &green), std::out_of_range);
}

TEST(TextureSystem, MissingOrBadFilesThrowNamingTheFile) {
  const fs::path dir = test::scratch_dir();
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const fs::path missing = dir / "no_such_texture.png";
  try {
    textures.add_texture(missing, "auto", channels);
    FAIL() << "no exception for a missing file";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
  }
  const fs::path not_image = dir / "notes.png";
  std::ofstream(not_image) << "this is not an image";
  try {
    textures.add_texture(not_image, "auto", channels);
    FAIL() << "no exception for a file that is not an image";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(not_image.string()), std::string::npos) << error.what();
  }
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  EXPECT_THROW(textures.add_texture(exr, "rec709", channels), std::runtime_error);
  EXPECT_EQ(textures.texture_count(), 0);
}

TEST(TextureSystem, SameFileTwiceGivesSameId) {
  const fs::path dir = test::scratch_dir();
  const fs::path png = write_png_codes(dir / "grey.png", 2, 2, std::vector<int>(12, 100));
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int first = textures.add_texture(png, "auto", channels);
  EXPECT_EQ(textures.add_texture(png, "auto", channels), first);
  EXPECT_EQ(textures.add_texture(dir / "." / "grey.png", "auto", channels), first);  // same absolute path
  EXPECT_EQ(textures.add_texture(png, "srgb", channels), first);  // "auto" is sRGB for 8-bit
  const int other = textures.add_texture(exr, "auto", channels);
  EXPECT_NE(other, first);
  EXPECT_EQ(textures.texture_count(), 2);
}

TEST(TextureSystem, ConversionCacheIsReusedAndRefreshedWhenTheSourceChanges) {
  const fs::path dir = test::scratch_dir();
  const fs::path cache = dir / "cache";
  const fs::path png = write_png_codes(dir / "grey.png", 2, 2, std::vector<int>(12, 188));
  auto cache_files = [&] {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(cache)) files.push_back(entry.path());
    return files;
  };
  int channels = 0;
  {
    OiioTextureProvider textures(cache);
    textures.add_texture(png, "auto", channels);
    EXPECT_NE(textures.stats().find("1 converted"), std::string::npos) << textures.stats();
  }
  ASSERT_EQ(cache_files().size(), 1u);  // one texture, no temporary or probe file left
  EXPECT_EQ(cache_files()[0].extension(), ".exr");
  {
    OiioTextureProvider textures(cache);
    textures.add_texture(png, "auto", channels);
    EXPECT_NE(textures.stats().find("1 from cache"), std::string::npos) << textures.stats();
  }
  // A new version of the source (other size / mtime) is converted again.
  write_png_codes(png, 2, 1, std::vector<int>(6, 255));
  fs::last_write_time(png, fs::last_write_time(png) + std::chrono::seconds(2));
  OiioTextureProvider textures(cache);
  const int id = textures.add_texture(png, "auto", channels);
  for (float value : rgb_at(textures, id, 0.5f, 0.5f, 0.0f)) EXPECT_NEAR(value, 1.0f, 1e-3f);
  EXPECT_EQ(cache_files().size(), 2u);
}

TEST(TextureSystem, LinearMipmappedTextureIsUsedWithoutConversion) {
  // A converted cache file is itself a linear, tiled, MIP-mapped texture (as maketx would write).
  const fs::path dir = test::scratch_dir();
  const fs::path exr = write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants);
  int channels = 0;
  { OiioTextureProvider(dir / "first").add_texture(exr, "linear", channels); }
  const fs::path texture_file = fs::directory_iterator(dir / "first")->path();
  OiioTextureProvider textures(dir / "second");
  const int id = textures.add_texture(texture_file, "auto", channels);
  EXPECT_NE(textures.stats().find("1 used as is"), std::string::npos) << textures.stats();
  EXPECT_TRUE(fs::is_empty(dir / "second"));
  const auto top_right = rgb_at(textures, id, 0.75f, 0.75f, 0.0f);
  EXPECT_FLOAT_EQ(top_right[1], 1.0f);
  EXPECT_EQ(textures.add_texture(exr, "Linear", channels), id + 1);  // colorspace names ignore case
}

TEST(TextureSystem, CacheDirectoryFromEnvironmentAndFallback) {
  const fs::path dir = test::scratch_dir();
  {
    EnvOverride ochre("OCHRE_CACHE_DIR", (dir / "ochre").string());
    EXPECT_EQ(default_texture_cache_dir(), dir / "ochre");
  }
  {
    EnvOverride ochre("OCHRE_CACHE_DIR", std::nullopt);
    EnvOverride xdg("XDG_CACHE_HOME", (dir / "xdg").string());
    EXPECT_EQ(default_texture_cache_dir(), dir / "xdg" / "ochre" / "textures");
    EnvOverride no_xdg("XDG_CACHE_HOME", "");
    EnvOverride home("HOME", (dir / "home").string());
    EXPECT_EQ(default_texture_cache_dir(), dir / "home" / ".cache" / "ochre" / "textures");
  }
  // A cache directory that cannot be created (its parent is a file) falls back to the temp dir.
  EnvOverride tmpdir("TMPDIR", dir.string());
  std::ofstream(dir / "a_file") << "x";
  OiioTextureProvider textures(dir / "a_file" / "cache");
  EXPECT_EQ(textures.cache_dir(), dir / "ochre-textures");
  int channels = 0;
  const int id =
      textures.add_texture(write_exr_rgb(dir / "quadrants.exr", 2, 2, kQuadrants), "auto", channels);
  EXPECT_FLOAT_EQ(rgb_at(textures, id, 0.25f, 0.75f, 0.0f)[0], 1.0f);
  EXPECT_NE(textures.stats().find("not writable"), std::string::npos) << textures.stats();
}

TEST(TextureSystem, ConcurrentLookupsMatchSequentialOnes) {
  const fs::path dir = test::scratch_dir();
  constexpr int kSize = 16;
  std::vector<float> rgb;
  for (int i = 0; i < kSize * kSize * 3; ++i) rgb.push_back(static_cast<float>((i * 7919) % 101) / 100.0f);
  OiioTextureProvider textures(dir / "cache");
  int channels = 0;
  const int id = textures.add_texture(write_exr_rgb(dir / "noise.exr", kSize, kSize, rgb), "auto", channels);

  constexpr int kLookups = 4000;
  auto run = [&](int begin, int end, std::vector<float>& out) {
    for (int i = begin; i < end; ++i) {
      const Vec2 uv{static_cast<float>(i % 97) / 97.0f, static_cast<float>(i % 89) / 89.0f * 1.5f};
      const float footprint = static_cast<float>(i % 5) * 0.03f;
      textures.lookup(id, uv, footprint, 0, 3, &out[static_cast<std::size_t>(i) * 3]);
    }
  };
  std::vector<float> sequential(kLookups * 3), concurrent(kLookups * 3);
  run(0, kLookups, sequential);
  std::thread first([&] { run(0, kLookups / 2, concurrent); });
  std::thread second([&] { run(kLookups / 2, kLookups, concurrent); });
  first.join();
  second.join();
  EXPECT_EQ(concurrent, sequential);
  EXPECT_GT(textures.memory_bytes(), 0u);
  EXPECT_NE(textures.stats().find("failed lookups 0"), std::string::npos) << textures.stats();
}

// Noise texture of a non-power-of-two size: its MIP levels have odd sizes.
fs::path write_noise_exr(const fs::path& path, int width, int height) {
  std::vector<float> rgb;
  for (int i = 0; i < width * height * 3; ++i) rgb.push_back(static_cast<float>((i * 7919) % 101) / 100.0f);
  return write_exr_rgb(path, width, height, rgb);
}

// Largest absolute difference between resident lookups and TextureSystem lookups at `footprint`.
float max_resident_difference(const fs::path& file, float footprint, int lookups) {
  const fs::path dir = file.parent_path();
  OiioTextureProvider resident(dir / "cache");
  OiioTextureProvider paged(dir / "cache", 0);
  int channels = 0;
  const int a = resident.add_texture(file, "auto", channels);
  const int b = paged.add_texture(file, "auto", channels);
  EXPECT_EQ(resident.resident_count(), 1);
  EXPECT_EQ(paged.resident_count(), 0);
  float worst = 0.0f;
  for (int i = 0; i < lookups; ++i) {
    const float u = static_cast<float>((i * 7) % 997) / 997.0f * 3.0f - 1.0f;  // beyond [0, 1): wrap
    const float v = static_cast<float>((i * 13) % 991) / 991.0f * 3.0f - 1.0f;
    const auto x = rgb_at(resident, a, u, v, footprint), y = rgb_at(paged, b, u, v, footprint);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(x[c] - y[c]));
  }
  return worst;
}

TEST(TextureSystem, ResidentLookupsEqualTheTextureSystemAtLevelZero) {
  const fs::path dir = test::scratch_dir();
  const fs::path file = write_noise_exr(dir / "noise.exr", 13, 7);
  EXPECT_LT(max_resident_difference(file, 0.0f, 2000), 2e-6f);
}

TEST(TextureSystem, ResidentMipFilteringStaysCloseToTheTextureSystem) {
  // Both blend the same MIP levels (read from the same file); they may choose the level blend
  // differently. Values lie in [0, 1]; neighbouring texels differ by up to 1.
  const fs::path dir = test::scratch_dir();
  const fs::path file = write_noise_exr(dir / "noise.exr", 64, 64);
  for (float footprint : {0.02f, 0.05f, 0.2f, 1.0f}) {
    const float worst = max_resident_difference(file, footprint, 2000);
    std::printf("footprint %.2f: max |resident - TextureSystem| = %.4f\n", footprint, worst);
    EXPECT_LT(worst, 0.08f) << "footprint " << footprint;
  }
}

TEST(TextureSystem, ResidentBudgetDecidesWhichTexturesStayInMemory) {
  const fs::path dir = test::scratch_dir();
  const fs::path file = write_noise_exr(dir / "noise.exr", 16, 16);
  // 16x16 RGB float + levels 8, 4, 2, 1: (256 + 64 + 16 + 4 + 1) x 12 bytes.
  const std::size_t bytes = (256 + 64 + 16 + 4 + 1) * 12;
  for (std::size_t budget : {bytes - 1, bytes}) {
    OiioTextureProvider textures(dir / "cache", budget);
    int channels = 0;
    const int id = textures.add_texture(file, "auto", channels);
    EXPECT_EQ(textures.resident_count(), budget >= bytes ? 1 : 0) << "budget " << budget;
    for (float value : rgb_at(textures, id, 0.5f / 16.0f, 1.0f - 0.5f / 16.0f, 0.0f))
      EXPECT_TRUE(std::isfinite(value));
    EXPECT_EQ(rgb_at(textures, id, 0.5f / 16.0f, 1.0f - 0.5f / 16.0f, 0.0f)[0], 0.0f);  // texel 0: (0 % 101)
  }
}

TEST(TextureSystem, LoadsSharedPhotoTexture) {
  OCHRE_REQUIRE_SHARED();
  const fs::path photo = test::shared_dir() / "assets/textures/mont-bego/roche_archer_2.jpg";
  OiioTextureProvider textures(test::scratch_dir() / "cache");
  int channels = 0;
  const int id = textures.add_texture(photo, "auto", channels);
  EXPECT_EQ(channels, 3);
  float sum = 0;
  for (int i = 0; i < 200; ++i) {
    const auto value = rgb_at(textures, id, static_cast<float>(i) / 200.0f,
                              static_cast<float>(i % 13) / 13.0f, static_cast<float>(i % 4) * 0.01f);
    for (float v : value) {
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
      sum += v;
    }
  }
  EXPECT_GT(sum, 0.0f);  // a photo of rock is not black
}

}  // namespace
}  // namespace ochre::texture_system_test
