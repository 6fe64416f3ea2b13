#pragma once
// ASCII case folding for names that are compared case-insensitively: file extensions (".PNG" is a PNG)
// and keywords of scene files (a texture's colorspace "sRGB").

#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace ochre {

inline std::string ascii_lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The extension of `file` with its dot, lowercase (".png"); empty when it has none.
inline std::string lower_extension(const std::filesystem::path& file) {
  return ascii_lowercase(file.extension().string());
}

inline bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

}  // namespace ochre
