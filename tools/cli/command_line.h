#pragma once
// Reading a program's command line with CLI11 (docs/cli.md, "Exit codes"): -h/--help and --version print
// and end the program with 0; any usage error (an unknown option, a missing or excluded one, a value that
// does not convert or fails its check) is bad input, exit code 2, with CLI11's message naming the option.
// And the checks CLI11 lacks: its numeric ranges let NaN through and its unsigned conversion reads "-1" as
// 2^64 - 1. This is the one header of the shared library that includes CLI11 (several seconds of compile
// per file): only the programs' main files include it.

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "spectra/input_error.h"

namespace ochre {

// Parses the command line into `app`. Returns false when the program is done (--help or --version printed:
// exit code 0); throws InputError with CLI11's message on a usage error (run_program: exit code 2).
inline bool parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    return true;
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    app.exit(e);
    return false;
  } catch (const CLI::ParseError& e) {
    throw InputError(std::string(e.what()) + " (see --help)");
  }
}

// Options read into uint64_t (seeds, counts): an integer in [0, 2^64 - 1] in decimal. CLI11 alone reads
// "-1" as 2^64 - 1 and saturates values beyond 2^64 - 1.
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

// An integer in [min, max] in decimal, for counts and numbers with a range of their own (frames): the
// message gives that range, never the type's ("-3" is not read as 2^64 - 3 nor reported against 2^64 - 1).
inline CLI::Validator unsigned_range_check(uint64_t min, uint64_t max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && value >= min && value <= max)
          return "";
        return "must be between " + std::to_string(min) + " and " + std::to_string(max) + " (got " + text +
               ")";
      },
      "INT in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
}

// A finite number in [min, max] (CLI::Range and CLI::PositiveNumber let NaN through: every comparison with it
// is false), or in (min, max] when min_open.
inline CLI::Validator finite_number_check(double min, double max, bool min_open, const std::string& what) {
  return CLI::Validator(
      [min, max, min_open, what](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && std::isfinite(value) &&
            (min_open ? value > min : value >= min) && value <= max)
          return "";
        return "expected " + what + ", got " + text;
      },
      what);
}
inline std::string option_bound_text(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}
inline CLI::Validator finite_range(double min, double max) {
  return finite_number_check(
      min, max, false, "a finite number in [" + option_bound_text(min) + ", " + option_bound_text(max) + "]");
}
inline CLI::Validator finite_non_negative() {
  return finite_number_check(0.0, std::numeric_limits<double>::max(), false, "a finite number >= 0");
}
inline CLI::Validator finite_positive() {
  return finite_number_check(0.0, std::numeric_limits<double>::max(), true, "a finite number > 0");
}

// A path option (an output, an input, a folder): a given but empty value is bad input, never read as
// "not given" (which would fall back on a default path and write over a file there).
inline CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "expected a path, got an empty string" : "";
      },
      "PATH");
}

}  // namespace ochre
