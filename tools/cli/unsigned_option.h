#pragma once
// A CLI11 check for options read into uint64_t (seeds): CLI11 alone reads "-1" as 2^64 - 1 and saturates
// values beyond 2^64 - 1; both must be usage errors (exit 2), like out-of-range integers in a scene.

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
#include <string>

namespace ochre {

inline CLI::Validator unsigned_64_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size()) return "";
        return "expected an integer in [0, 18446744073709551615], got " + text;
      },
      "UINT64");
}

}  // namespace ochre
