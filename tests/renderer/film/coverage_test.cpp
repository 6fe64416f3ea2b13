// Coverage of split renders: text forms, and the check that parts hold every sample of every pixel once.
#include "renderer/film/coverage.h"

#include <gtest/gtest.h>

namespace ochre::coverage_test {
namespace {

TEST(RenderSplit, ParsesAndFormatsRangesRectsAndParts) {
  EXPECT_EQ(parse_sample_range("3:17"), (SampleRange{3, 17}));
  EXPECT_EQ(parse_sample_range("0:4294967295"), (SampleRange{0, 4294967295u}));
  for (const char* bad :
       {"5:3", "4:4", "", ":", "1:", ":2", "-1:3", "+1:3", "1:2:3", "1 :2", "0:4294967296", "a:b"})
    EXPECT_FALSE(parse_sample_range(bad)) << bad;
  EXPECT_EQ(parse_pixel_rect("1,2,30,40"), (PixelRect{1, 2, 30, 40}));
  for (const char* bad : {"1,2,1,40", "1,2,30,2", "1,2,30", "1,2,30,40,5", "-1,0,2,2", "0,0,2,2,"})
    EXPECT_FALSE(parse_pixel_rect(bad)) << bad;
  EXPECT_EQ(parse_part("2/5"), (std::pair<uint32_t, uint32_t>{2, 5}));
  for (const char* bad : {"5/5", "0/0", "1", "1/2/3", "-1/2"}) EXPECT_FALSE(parse_part(bad)) << bad;
  EXPECT_EQ(format_sample_range({3, 17}), "3:17");
  EXPECT_EQ(format_pixel_rect({1, 2, 30, 40}), "1,2,30,40");
}

// Equal parts tile [0, spp) without gap or overlap, also when spp is not a multiple of the count.
TEST(RenderSplit, PartsOfSamplesTileTheRange) {
  for (uint32_t spp : {1u, 7u, 64u, 1000u})
    for (uint32_t count = 1; count <= spp && count <= 13; ++count) {
      uint32_t next = 0;
      for (uint32_t i = 0; i < count; ++i) {
        const SampleRange r = part_of_samples(i, count, spp);
        EXPECT_EQ(r.begin, next);
        EXPECT_GT(r.end, r.begin);
        next = r.end;
      }
      EXPECT_EQ(next, spp);
    }
}

TEST(RenderSplit, GridTilesCoverTheImageExactlyOnce) {
  EXPECT_EQ(parse_grid_tile("5/3x2")->index, 5u);
  EXPECT_EQ(parse_grid_tile("5/3x2")->columns, 3u);
  EXPECT_EQ(parse_grid_tile("0/1x1")->rows, 1u);
  for (const char* bad : {"6/3x2", "0/0x2", "0/2x0", "1/2", "1/2x", "a/2x2", "1/2x2x2", "-1/2x2"})
    EXPECT_FALSE(parse_grid_tile(bad)) << bad;
  EXPECT_EQ(tile_rect({4, 3, 2}, 100, 51), (PixelRect{33, 25, 66, 51}));
  for (const auto& [columns, rows] : {std::pair{3u, 2u}, std::pair{7u, 5u}, std::pair{1u, 9u}}) {
    std::vector<SourcedPiece> tiles;
    for (uint32_t i = 0; i < columns * rows; ++i)
      tiles.push_back({{tile_rect({i, columns, rows}, 23, 17), {0, 4}}, "t"});
    EXPECT_TRUE(check_coverage(tiles, 23, 17, 4).complete()) << columns << "x" << rows;
  }
  EXPECT_TRUE(tile_rect({0, 30, 1}, 20, 10).empty());
}

TEST(Coverage, TextFormRoundTrips) {
  const std::vector<CoveragePiece> pieces = {{{0, 0, 8, 4}, {0, 3}}, {{2, 1, 5, 4}, {3, 9}}};
  EXPECT_EQ(format_coverage(pieces), "0,0,8,4:0:3;2,1,5,4:3:9");
  EXPECT_EQ(parse_coverage(format_coverage(pieces)), pieces);
  EXPECT_EQ(parse_coverage(""), std::vector<CoveragePiece>{});
  for (const char* bad : {"0,0,8,4", "0,0,8,4:3", "0,0,8,4:0:3;", "0,0,8,4:0:3;;1,1,2,2:0:1", "x"})
    EXPECT_FALSE(parse_coverage(bad)) << bad;
}

TEST(Coverage, SimplifyJoinsTouchingRangesOfOneRect) {
  const PixelRect a{0, 0, 4, 4}, b{4, 0, 8, 4};
  EXPECT_EQ(simplify_coverage({{a, {4, 8}}, {b, {0, 2}}, {a, {0, 4}}, {a, {9, 12}}}),
            (std::vector<CoveragePiece>{{a, {0, 8}}, {a, {9, 12}}, {b, {0, 2}}}));
}

TEST(Coverage, CompleteSplitsPass) {
  // Sample ranges, then tiles, then tiles of which one is split again by samples.
  EXPECT_TRUE(
      check_coverage({{{{0, 0, 8, 6}, {0, 5}}, "a"}, {{{0, 0, 8, 6}, {5, 9}}, "b"}}, 8, 6, 9).complete());
  EXPECT_TRUE(
      check_coverage({{{{0, 0, 3, 6}, {0, 9}}, "a"}, {{{3, 0, 8, 6}, {0, 9}}, "b"}}, 8, 6, 9).complete());
  EXPECT_TRUE(check_coverage({{{{0, 0, 3, 6}, {0, 9}}, "a"},
                              {{{3, 0, 8, 2}, {0, 9}}, "b"},
                              {{{3, 2, 8, 6}, {0, 4}}, "c"},
                              {{{3, 2, 8, 6}, {4, 9}}, "d"}},
                             8, 6, 9)
                  .complete());
}

TEST(Coverage, NamesMissingSamplesAndRegions) {
  const CoverageReport ranges =
      check_coverage({{{{0, 0, 8, 6}, {0, 3}}, "a"}, {{{0, 0, 8, 6}, {5, 7}}, "b"}}, 8, 6, 9);
  EXPECT_TRUE(ranges.overlaps.empty());
  EXPECT_EQ(ranges.missing,
            (std::vector<std::string>{"samples 3:5 of every pixel", "samples 7:9 of every pixel"}));
  // Four tiles of 4x3, one missing; one with half its samples.
  const CoverageReport tiles = check_coverage(
      {{{{0, 0, 4, 3}, {0, 9}}, "a"}, {{{4, 0, 8, 3}, {0, 9}}, "b"}, {{{0, 3, 4, 6}, {0, 4}}, "c"}}, 8, 6, 9);
  EXPECT_EQ(tiles.missing,
            (std::vector<std::string>{"samples 4:9 of region 0,3,4,6", "samples 0:9 of region 4,3,8,6"}));
  // Cells with the same gap join into one rectangle.
  const CoverageReport band =
      check_coverage({{{{0, 0, 8, 2}, {0, 9}}, "a"}, {{{0, 5, 3, 6}, {0, 9}}, "b"}}, 8, 6, 9);
  EXPECT_EQ(band.missing,
            (std::vector<std::string>{"samples 0:9 of region 0,2,8,5", "samples 0:9 of region 3,5,8,6"}));
}

TEST(Coverage, NamesOverlapsWithBothFiles) {
  const CoverageReport r = check_coverage({{{{0, 0, 8, 6}, {0, 5}}, "a.exr"},
                                           {{{2, 0, 8, 6}, {4, 9}}, "b.exr"},
                                           {{{0, 0, 2, 6}, {5, 9}}, "c.exr"}},
                                          8, 6, 9);
  EXPECT_TRUE(r.missing.empty());
  EXPECT_EQ(r.overlaps,
            (std::vector<std::string>{"a.exr and b.exr both hold samples 4:5 of region 2,0,8,6"}));
}

}  // namespace
}  // namespace ochre::coverage_test
