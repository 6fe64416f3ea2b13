#include "spectra/byte_size.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace ochre {

namespace {

struct Unit {
  char letter;
  const char* name;
  std::uint64_t bytes;
};

constexpr std::array<Unit, 4> kUnits = {
    {{'K', "KiB", kKiB}, {'M', "MiB", kMiB}, {'G', "GiB", kGiB}, {'T', "TiB", kTiB}}};

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

}  // namespace

std::string format_bytes(std::uint64_t bytes) {
  const Unit* unit = nullptr;
  for (const Unit& u : kUnits)
    if (bytes >= u.bytes) unit = &u;
  if (unit == nullptr) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  const double value = static_cast<double>(bytes) / static_cast<double>(unit->bytes);
  char text[64];
  if (value >= 100.0 || std::fmod(std::round(value * 10.0), 10.0) == 0.0)
    std::snprintf(text, sizeof text, "%.0f %s", std::round(value), unit->name);
  else
    std::snprintf(text, sizeof text, "%.1f %s", value, unit->name);
  return text;
}

std::optional<std::uint64_t> parse_byte_size(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end == text.data()) return std::nullopt;
  std::string_view suffix(end, static_cast<size_t>(text.data() + text.size() - end));
  std::uint64_t scale = 1;
  if (!suffix.empty() && !iequals(suffix, "B")) {
    const Unit* unit = nullptr;
    for (const Unit& u : kUnits)
      if (std::toupper(static_cast<unsigned char>(suffix.front())) == u.letter) unit = &u;
    if (unit == nullptr) return std::nullopt;
    suffix.remove_prefix(1);
    if (!suffix.empty() && !iequals(suffix, "B") && !iequals(suffix, "iB")) return std::nullopt;
    scale = unit->bytes;
  }
  const double bytes = std::floor(value * static_cast<double>(scale));
  // 2^64 as a double: anything at or above it does not fit.
  if (!(bytes >= 1.0) || !(bytes < 18446744073709551616.0)) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

}  // namespace ochre
