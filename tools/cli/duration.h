#pragma once
// Durations on the command line (--checkpoint-interval, --time-limit): "90" or "90s" seconds, "10m"
// minutes, "2h" hours, "1h30m", with decimals allowed ("1.5h"); at most a year.

#include <optional>
#include <string_view>

namespace ochre {

// Seconds, or nullopt when the text is malformed, zero, negative or longer than a year.
std::optional<double> parse_duration(std::string_view text);

}  // namespace ochre
