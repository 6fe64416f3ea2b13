// MipPyramid: bilinear lookups at texel centres and between them, periodic wrap, the level chosen for a
// footprint and the blend between two levels, on hand-made pyramids with known values.

#include "renderer/texture/mip_pyramid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "support/awkward_floats.h"

namespace ochre::mip_pyramid_test {
namespace {

// Level 0: 4x2 single-channel ramp 0..7 (row 0 = top); level 1: 2x1 of 10, 20; level 2: 1x1 of 100.
MipPyramid ramp_pyramid() {
  std::vector<MipPyramid::Level> levels(3);
  levels[0] = {4, 2, {0, 1, 2, 3, 4, 5, 6, 7}};
  levels[1] = {2, 1, {10, 20}};
  levels[2] = {1, 1, {100}};
  return MipPyramid(std::move(levels), 1);
}

float at(const MipPyramid& p, float s, float t, float footprint) {
  float out = -1.0f;
  p.lookup(s, t, footprint, 0, 1, &out);
  return out;
}

TEST(MipPyramid, TexelCentresAreExact) {
  const MipPyramid p = ramp_pyramid();
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i)
      EXPECT_FLOAT_EQ(at(p, (i + 0.5f) / 4.0f, (j + 0.5f) / 2.0f, 0.0f), static_cast<float>(j * 4 + i));
}

TEST(MipPyramid, BilinearBetweenCentresAndPeriodicWrap) {
  const MipPyramid p = ramp_pyramid();
  // Halfway between texels 1 and 2 of the top row, a quarter of the way down to the bottom row.
  EXPECT_FLOAT_EQ(at(p, 0.5f, 0.25f + 0.125f, 0.0f), 0.75f * 1.5f + 0.25f * 5.5f);
  // s = 0: halfway between the last and the first texel of a row (wrap).
  EXPECT_FLOAT_EQ(at(p, 0.0f, 0.25f, 0.0f), 1.5f);
  // Whole periods away, negative too.
  EXPECT_FLOAT_EQ(at(p, 0.375f - 3.0f, 0.75f + 5.0f, 0.0f), 5.0f);
}

TEST(MipPyramid, FootprintSelectsAndBlendsLevels) {
  const MipPyramid p = ramp_pyramid();
  const float s = 0.25f, t = 0.5f;  // level 1: the centre of its first texel (10); level 2: 100
  // One texel of level 0 or less: level 0 only.
  EXPECT_FLOAT_EQ(at(p, s, t, 0.25f), at(p, s, t, 0.0f));
  // Two texels of level 0 (footprint 2 / 4): exactly level 1.
  EXPECT_FLOAT_EQ(at(p, s, t, 0.5f), 10.0f);
  // Four texels: level 2; more: still the last level.
  EXPECT_FLOAT_EQ(at(p, s, t, 1.0f), 100.0f);
  EXPECT_FLOAT_EQ(at(p, s, t, 50.0f), 100.0f);
  // Three texels: log2(3) - 1 of the way from level 1 to level 2.
  const float blend = std::log2(3.0f) - 1.0f;
  EXPECT_NEAR(at(p, s, t, 0.75f), (1.0f - blend) * 10.0f + blend * 100.0f, 1e-4f);
  // Non-finite footprints read level 0; non-finite coordinates give 0.
  EXPECT_FLOAT_EQ(at(p, s, t, NAN), at(p, s, t, 0.0f));
  EXPECT_FLOAT_EQ(at(p, NAN, t, 0.0f), 0.0f);
}

TEST(MipPyramid, ChannelsAndSizesAreChecked) {
  std::vector<MipPyramid::Level> levels(1);
  levels[0] = {2, 1, {1, 2, 3, 4, 5, 6}};
  const MipPyramid p(levels, 3);
  float out[2] = {-1, -1};
  p.lookup(0.25f, 0.5f, 0.0f, 1, 2, out);  // channels 1..2 of texel 0
  EXPECT_FLOAT_EQ(out[0], 2.0f);
  EXPECT_FLOAT_EQ(out[1], 3.0f);
  EXPECT_EQ(p.memory_bytes(), 6 * sizeof(float));
  EXPECT_THROW(MipPyramid(levels, 2), std::invalid_argument);
  EXPECT_THROW(MipPyramid({}, 1), std::invalid_argument);
}

// NaN, infinities and huge coordinates (docs/nodes.md, "Non-finite values").
TEST(MipPyramid, AnyCoordinateAndFootprintIsSafe) {
  const MipPyramid p = ramp_pyramid();
  for (float s : test::awkward_floats())
    for (float t : test::awkward_floats())
      for (float footprint : {test::kNaN, test::kInf, 1e30f, 0.0f, 0.3f}) {
        const float v = at(p, s, t, footprint);
        EXPECT_TRUE(std::isfinite(v)) << s << ", " << t << ", " << footprint;
        if (!std::isfinite(s) || !std::isfinite(t)) {
          EXPECT_EQ(v, 0.0f);
        }
      }
}

TEST(MipPyramid, HugeCoordinatesWrapToZero) {
  const MipPyramid p = ramp_pyramid();
  // s * width overflows to infinity for s near the largest float: a float -> int conversion of that is
  // undefined. Every float from 2^23 on is an integer: under a period of 1 it is the place 0.
  for (float huge : {1e30f, test::kLargest, -test::kLargest, 8388608.0f, 3e38f}) {
    EXPECT_EQ(at(p, huge, 0.25f, 0.0f), at(p, 0.0f, 0.25f, 0.0f)) << huge;
    EXPECT_EQ(at(p, 0.625f, huge, 0.0f), at(p, 0.625f, 0.0f, 0.0f)) << huge;
  }
  EXPECT_EQ(at(p, 1.625f, 0.25f, 0.0f), at(p, 0.625f, 0.25f, 0.0f));  // ordinary wrap kept
}

}  // namespace
}  // namespace ochre::mip_pyramid_test
