#pragma once
// What a partial render holds (docs/distributed.md): a list of pieces, each a range of samples of a
// rectangle of pixels. A single `ochre render --sample-range/--region` holds one piece; a merge of parts
// holds theirs. Merging checks that the pieces of all parts cover samples [0, spp) of every pixel exactly
// once, and names what is missing or held twice in the text forms of the command line, so that the
// missing work can be rendered by `ochre render --region R --sample-range A:B`.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/film/render_split.h"

namespace ochre {

struct CoveragePiece {
  PixelRect rect;
  SampleRange samples;
  bool operator==(const CoveragePiece&) const = default;
};

// "x0,y0,x1,y1:A:B;x0,y0,x1,y1:A:B" (the ochre.coverage attribute); "" for no piece.
std::string format_coverage(const std::vector<CoveragePiece>& pieces);
// The inverse; nullopt when malformed.
std::optional<std::vector<CoveragePiece>> parse_coverage(std::string_view text);

// Merges pieces of one rectangle whose sample ranges touch ([0,8) and [8,16) become [0,16)), so a merged
// file's coverage stays short. Order: by rectangle, then by first sample.
std::vector<CoveragePiece> simplify_coverage(std::vector<CoveragePiece> pieces);

// The smallest rectangle holding every piece.
PixelRect bounding_rect(const std::vector<CoveragePiece>& pieces);

struct SourcedPiece {
  CoveragePiece piece;
  std::string source;  // the file it comes from, for messages
};

struct CoverageReport {
  // "a.exr and b.exr both hold samples 16:32 of region 0,0,64,64"
  std::vector<std::string> overlaps;
  // "samples 32:64 of every pixel", "samples 0:16 of region 0,0,128,64"
  std::vector<std::string> missing;
  bool complete() const { return overlaps.empty() && missing.empty(); }
};

// Checks the pieces against samples [0, spp) of every pixel of a width x height image. The work is
// proportional to (number of distinct rectangle edges)^2 x pieces.
CoverageReport check_coverage(const std::vector<SourcedPiece>& pieces, int width, int height, uint32_t spp);

}  // namespace ochre
