#pragma once
// Byte counts for people and from people: "3.2 GiB", "256 MiB" in messages, and sizes such as "8G" or
// "512M" given on the command line (--memory-limit). Units are binary: K = 1024, M = 1024^2, ...

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ochre {

inline constexpr std::uint64_t kKiB = std::uint64_t{1} << 10;
inline constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
inline constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;
inline constexpr std::uint64_t kTiB = std::uint64_t{1} << 40;

// "512 bytes", "1.5 KiB", "256 MiB", "3.2 GiB", "412 GiB": the largest unit that keeps the value >= 1,
// one decimal below 100 (dropped when it is 0).
std::string format_bytes(std::uint64_t bytes);

// "8G", "8GiB", "8GB", "512M", "1.5g", "64k", "1048576" (bytes): a positive number with an optional
// unit K, M, G or T (case-insensitive, powers of 1024, optionally followed by "iB" or "B"). Returns
// nothing when the text is malformed, zero, or larger than 2^64 - 1 bytes.
std::optional<std::uint64_t> parse_byte_size(std::string_view text);

}  // namespace ochre
