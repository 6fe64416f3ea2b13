#pragma once
// Checks of `ochre render --frames N --first-frame K --fps F` (docs/cli.md#frame-sequences).

#include <cstdint>
#include <optional>
#include <string>

namespace ochre {

inline constexpr uint64_t kMaxFrames = 1000000;         // frames in one sequence
inline constexpr uint64_t kMaxFrameNumber = 999999999;  // 9 digits in a file name
inline constexpr double kMaxFps = 10000.0;

// "" when the given options are valid, else the message (the option and what is wrong with it).
std::string check_frame_options(std::optional<uint64_t> frames, std::optional<uint64_t> first_frame,
                                std::optional<double> fps);

}  // namespace ochre
