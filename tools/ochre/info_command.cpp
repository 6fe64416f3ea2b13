#include "tools/ochre/info_command.h"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <iostream>

#include "renderer/output/partial_sums.h"
#include "renderer/output/render_identity.h"
#include "tools/cli/program.h"
#include "tools/ochre/checkpoint_resume.h"

namespace ochre {

namespace {

// A count of samples per pixel: whole, or with two decimals when the pieces hold different counts.
std::string per_pixel(double samples) {
  return samples == std::floor(samples) ? fmt::format("{:.0f}", samples) : fmt::format("{:.2f}", samples);
}

std::string describe(const PartialSumsFile& file) {
  const PartialSumsHeader& h = file.header();
  const auto target_note = h.notes.find("ochre.checkpoint.target");
  const bool checkpoint = target_note != h.notes.end();
  std::string line = fmt::format("{}: {}", file.path().string(), checkpoint ? "checkpoint" : "partial sums");
  if (const std::string* frame = identity_field(h.identity, "ochre.frame"); frame && !frame->empty())
    line += ", frame " + *frame;
  line += fmt::format(", region {} of {}x{}", format_pixel_rect(h.rect), h.image_width, h.image_height);

  // The samples held, per pixel of the file's region on average (exact for a single piece).
  double held = 0.0;
  for (const CoveragePiece& piece : h.coverage)
    held += static_cast<double>(piece.rect.width()) * piece.rect.height() *
            (piece.samples.end - piece.samples.begin);
  held /= static_cast<double>(h.rect.width()) * h.rect.height();
  std::string samples;
  if (h.coverage.empty())
    samples = "no samples";
  else if (h.coverage.size() == 1 && h.coverage.front().rect == h.rect)
    samples = "samples " + format_sample_range(h.coverage.front().samples);
  else
    samples = fmt::format("samples in {} pieces", h.coverage.size());
  const std::optional<SampleRange> target =
      checkpoint ? parse_sample_range(target_note->second) : std::nullopt;
  if (!target) return line + fmt::format(", {} ({} per pixel)", samples, per_pixel(held));

  const double aimed = target->end - target->begin;
  line += fmt::format(", {} of {} ({} of {} per pixel, {:.1f} %)", samples, format_sample_range(*target),
                      per_pixel(held), per_pixel(aimed), 100.0 * held / aimed);
  if (const std::optional<double> seconds = recorded_seconds(h)) {
    line += fmt::format(", {:.2f} s of rendering", *seconds);
    if (held > 0.0) line += fmt::format(", about {:.0f} s left", (aimed - held) * *seconds / held);
  }
  return line;
}

}  // namespace

int run_info(const InfoCommand& command) {
  int exit_code = kExitDone;
  for (const std::string& path : command.parts) {
    try {
      const PartialSumsFile file(path);
      std::cout << describe(file) << "\n";
    } catch (const std::exception&) {
      // Reported naming the file; the other files are still listed.
      const int code = report_current_exception();
      if (exit_code == kExitDone) exit_code = code;
    }
  }
  std::cout.flush();
  return exit_code;
}

}  // namespace ochre
