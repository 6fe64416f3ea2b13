#include "renderer/json/json_file.h"

#include <fmt/format.h>

#include "renderer/json/json_duplicate_keys.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

// "line L, column C" of a byte offset, for JSON syntax errors.
std::string line_column(const std::string& text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return fmt::format("line {}, column {}", line, column);
}

}  // namespace

nlohmann::json read_json_file(const std::filesystem::path& file, const char* what) {
  std::error_code error;
  if (!std::filesystem::exists(file, error))
    throw InputError(fmt::format("{}: cannot open {}", file.string(), what));
  const std::string text = read_input_file(file, InputKind{what, kJsonFileLimit});
  try {
    return parse_json_rejecting_duplicate_keys(text, file.string());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(
        fmt::format("{}: {}: malformed JSON ({})", file.string(), line_column(text, e.byte), e.what()));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: malformed JSON ({})", file.string(), e.what()));
  }
}

}  // namespace ochre
