#include "tools/cli/duration.h"

#include <charconv>
#include <cmath>

namespace ochre {

std::optional<double> parse_duration(std::string_view text) {
  double total = 0.0;
  if (text.empty()) return std::nullopt;
  const char* p = text.data();
  const char* const end_of_text = text.data() + text.size();
  const std::string_view units = "hms";
  size_t last_unit = std::string_view::npos;  // units must come in the order h, m, s, each once
  while (p != end_of_text) {
    if (!(*p >= '0' && *p <= '9')) return std::nullopt;
    double value = 0.0;
    const auto [end, error] = std::from_chars(p, end_of_text, value, std::chars_format::fixed);
    if (error != std::errc() || !std::isfinite(value)) return std::nullopt;
    p = end;
    double scale = 1.0;
    if (p != end_of_text) {
      const size_t unit = units.find(*p);
      if (unit == std::string_view::npos || (last_unit != std::string_view::npos && unit <= last_unit))
        return std::nullopt;
      last_unit = unit;
      scale = unit == 0 ? 3600.0 : unit == 1 ? 60.0 : 1.0;
      ++p;
    } else if (last_unit != std::string_view::npos) {
      return std::nullopt;  // "1h30": a bare number only on its own
    }
    total += value * scale;
  }
  if (!(total > 0.0) || total > 366.0 * 86400.0) return std::nullopt;
  return total;
}

}  // namespace ochre
