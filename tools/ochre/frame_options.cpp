#include "tools/ochre/frame_options.h"

#include <fmt/format.h>

#include <cmath>

namespace ochre {

std::string check_frame_options(std::optional<uint64_t> frames, std::optional<uint64_t> first_frame,
                                std::optional<double> fps) {
  if (!frames) {
    if (fps) return "--fps: needs --frames (a single render shows every flame at its mean)";
    if (first_frame) return "--first-frame: needs --frames";
    return "";
  }
  if (*frames < 1 || *frames > kMaxFrames)
    return fmt::format("--frames: must be between 1 and {} (got {})", kMaxFrames, *frames);
  const uint64_t first = first_frame.value_or(1);
  if (first < 1 || first > kMaxFrameNumber)
    return fmt::format("--first-frame: must be between 1 and {} (got {})", kMaxFrameNumber, first);
  if (first + *frames - 1 > kMaxFrameNumber)
    return fmt::format("--frames: the last frame {} would exceed {}", first + *frames - 1, kMaxFrameNumber);
  if (fps && !(std::isfinite(*fps) && *fps > 0.0 && *fps <= kMaxFps))
    return fmt::format("--fps: must be a number in (0, {}] (got {})", kMaxFps, *fps);
  return "";
}

}  // namespace ochre
