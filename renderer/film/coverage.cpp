#include "renderer/film/coverage.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <tuple>

namespace ochre {

namespace {

bool rect_less(const PixelRect& a, const PixelRect& b) {
  return std::tie(a.y0, a.x0, a.y1, a.x1) < std::tie(b.y0, b.x0, b.y1, b.x1);
}

// The sorted, distinct values of the edges along one axis, with the image's bounds.
std::vector<int> cuts(const std::vector<SourcedPiece>& pieces, int size, bool x_axis) {
  std::set<int> values = {0, size};
  for (const SourcedPiece& p : pieces) {
    const PixelRect& r = p.piece.rect;
    values.insert(std::clamp(x_axis ? r.x0 : r.y0, 0, size));
    values.insert(std::clamp(x_axis ? r.x1 : r.y1, 0, size));
  }
  return {values.begin(), values.end()};
}

struct Cell {
  PixelRect rect;
  std::vector<SampleRange> gaps;
};

// The sample ranges of [0, spp) that no piece holds, and the overlaps, of one cell (every piece either
// contains the cell or misses it).
std::vector<SampleRange> cell_gaps(const std::vector<const SourcedPiece*>& holding, uint32_t spp,
                                   const PixelRect& cell, std::set<std::string>& overlaps) {
  std::vector<SampleRange> gaps;
  uint32_t next = 0;
  const SourcedPiece* previous = nullptr;
  for (const SourcedPiece* p : holding) {
    const SampleRange s = p->piece.samples;
    if (s.begin > next) gaps.push_back({next, s.begin});
    if (previous && s.begin < next)
      overlaps.insert(fmt::format("{} and {} both hold samples {} of region {}", previous->source, p->source,
                                  format_sample_range({s.begin, std::min(next, s.end)}),
                                  format_pixel_rect(cell)));
    if (s.end > next) {
      next = s.end;
      previous = p;
    }
  }
  if (next < spp) gaps.push_back({next, spp});
  return gaps;
}

// Joins cells with the same gaps: along each row of cells, then rows with the same spans.
std::vector<Cell> join_cells(const std::vector<Cell>& cells) {
  std::vector<Cell> rows;
  for (const Cell& c : cells) {
    if (!rows.empty() && rows.back().rect.y0 == c.rect.y0 && rows.back().rect.x1 == c.rect.x0 &&
        rows.back().gaps == c.gaps)
      rows.back().rect.x1 = c.rect.x1;
    else
      rows.push_back(c);
  }
  std::vector<Cell> joined;
  for (const Cell& c : rows) {
    auto above = std::find_if(joined.begin(), joined.end(), [&](const Cell& j) {
      return j.rect.x0 == c.rect.x0 && j.rect.x1 == c.rect.x1 && j.rect.y1 == c.rect.y0 && j.gaps == c.gaps;
    });
    if (above != joined.end())
      above->rect.y1 = c.rect.y1;
    else
      joined.push_back(c);
  }
  return joined;
}

}  // namespace

std::string format_coverage(const std::vector<CoveragePiece>& pieces) {
  std::string text;
  for (const CoveragePiece& p : pieces) {
    if (!text.empty()) text += ';';
    text += format_pixel_rect(p.rect) + ':' + format_sample_range(p.samples);
  }
  return text;
}

std::optional<std::vector<CoveragePiece>> parse_coverage(std::string_view text) {
  std::vector<CoveragePiece> pieces;
  while (!text.empty()) {
    const size_t end = text.find(';');
    const std::string_view item = text.substr(0, end);
    const size_t colon = item.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    const auto rect = parse_pixel_rect(item.substr(0, colon));
    const auto samples = parse_sample_range(item.substr(colon + 1));
    if (!rect || !samples) return std::nullopt;
    pieces.push_back({*rect, *samples});
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
    if (text.empty()) return std::nullopt;  // a trailing ';'
  }
  return pieces;
}

std::vector<CoveragePiece> simplify_coverage(std::vector<CoveragePiece> pieces) {
  std::sort(pieces.begin(), pieces.end(), [](const CoveragePiece& a, const CoveragePiece& b) {
    if (a.rect != b.rect) return rect_less(a.rect, b.rect);
    return a.samples.begin < b.samples.begin;
  });
  std::vector<CoveragePiece> simple;
  for (const CoveragePiece& p : pieces) {
    if (!simple.empty() && simple.back().rect == p.rect && simple.back().samples.end == p.samples.begin)
      simple.back().samples.end = p.samples.end;
    else
      simple.push_back(p);
  }
  return simple;
}

PixelRect bounding_rect(const std::vector<CoveragePiece>& pieces) {
  if (pieces.empty()) return {};
  PixelRect box = pieces.front().rect;
  for (const CoveragePiece& p : pieces) {
    box.x0 = std::min(box.x0, p.rect.x0);
    box.y0 = std::min(box.y0, p.rect.y0);
    box.x1 = std::max(box.x1, p.rect.x1);
    box.y1 = std::max(box.y1, p.rect.y1);
  }
  return box;
}

CoverageReport check_coverage(const std::vector<SourcedPiece>& pieces, int width, int height, uint32_t spp) {
  const std::vector<int> xs = cuts(pieces, width, true), ys = cuts(pieces, height, false);
  std::vector<const SourcedPiece*> sorted;
  for (const SourcedPiece& p : pieces) sorted.push_back(&p);
  std::stable_sort(sorted.begin(), sorted.end(), [](const SourcedPiece* a, const SourcedPiece* b) {
    return a->piece.samples.begin < b->piece.samples.begin;
  });
  std::set<std::string> overlaps;
  std::vector<Cell> cells_with_gaps;
  for (size_t j = 0; j + 1 < ys.size(); ++j)
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      const PixelRect cell{xs[i], ys[j], xs[i + 1], ys[j + 1]};
      std::vector<const SourcedPiece*> holding;
      for (const SourcedPiece* p : sorted)
        if (p->piece.rect.contains(cell)) holding.push_back(p);
      std::vector<SampleRange> gaps = cell_gaps(holding, spp, cell, overlaps);
      if (!gaps.empty()) cells_with_gaps.push_back({cell, std::move(gaps)});
    }
  CoverageReport report;
  report.overlaps.assign(overlaps.begin(), overlaps.end());
  const PixelRect image{0, 0, width, height};
  for (const Cell& c : join_cells(cells_with_gaps))
    for (const SampleRange& gap : c.gaps)
      report.missing.push_back(
          c.rect == image
              ? fmt::format("samples {} of every pixel", format_sample_range(gap))
              : fmt::format("samples {} of region {}", format_sample_range(gap), format_pixel_rect(c.rect)));
  return report;
}

}  // namespace ochre
